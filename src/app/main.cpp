// pierre: the command line. Sub-commands live in their own files (commands.hpp); this file
// parses, dispatches and turns every failure into a message and an exit code:
// help and --version 0, usage errors and bad input 2, anything unexpected 3.
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "run_steps.hpp"
#include "pierre/io/input_error.hpp"
#include "pierre/io/nearest_name.hpp"
#include "pierre/io/output_folder.hpp"
#include "pierre/io/version.hpp"

#ifndef PIERRE_VERSION
#define PIERRE_VERSION "unknown"
#endif

namespace {

// A failed write to stdout (a full disk, a reader that closed the pipe): what the command
// printed is lost, so a script reading it must not take exit 0, nor an "internal error" for a
// fault of where the output went.
int lost_stdout(bool writes_results = false) {
  const int err = errno;
  std::fputs(("error: cannot write to standard output: " + std::string(std::strerror(err)) +
              (writes_results ? " (the result files, if any, were written)" : "") + "\n")
                 .c_str(),
             stderr);
  return pierre::app::kExitInternal;
}

bool is_command(const char* word, const std::vector<CLI::App*>& subs) {
  return std::any_of(subs.begin(), subs.end(), [&](CLI::App* c) { return c->check_name(word); });
}

// A misspelt command (CLI11 says only that one is required): named, with the commands there
// are. False when the first argument is an option or a command.
bool said_misspelt_command(int argc, char** argv, const std::vector<CLI::App*>& subs) {
  if (argc < 2 || argv[1][0] == '-' || is_command(argv[1], subs)) return false;
  std::fprintf(stderr, "%s: not a command; expected run, check or validate (pierre --help)\n", argv[1]);
  return true;
}

// A failure the user can mend (where the results go, how many to run): "error: ..." on stderr,
// after what stdout holds, and exit 2 as for bad input.
int said_as_input(const char* what, const std::exception& e) {
  std::fflush(stdout);
  std::fputs(("error: " + std::string(what) + e.what() + "\n").c_str(), stderr);
  return pierre::app::kExitInput;
}

// The first argument that is a long option of some command written with a single dash
// ("-out", "-seed=3"), or "" when there is none.
std::string single_dash_long_option(int argc, char** argv, const std::vector<CLI::App*>& apps) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") break;
    if (a.size() < 3 || a[0] != '-' || a[1] == '-') continue;
    const std::string name = a.substr(1, a.find('=') - 1);
    for (const CLI::App* c : apps)
      for (const CLI::Option* o : c->get_options())
        for (const std::string& l : o->get_lnames())
          if (l == name) return a;
  }
  return {};
}

// "; did you mean --rules?" for an option of `c` near `found` ("--rule"), else "".
std::string nearest_option_hint(const CLI::App& c, const std::string& found) {
  std::vector<std::string> names;
  for (const CLI::Option* o : c.get_options())
    for (const std::string& l : o->get_lnames()) names.push_back(l);
  const std::size_t from = found.find_first_not_of('-');
  if (from == std::string::npos) return {};  // "---": nothing to compare
  const std::string bare = found.substr(from, found.find('=') - from);
  const std::string near = pierre::io::detail::nearest_name(bare, names);
  return near.empty() ? std::string() : "; did you mean --" + near + "?";
}

// A word (not an option, not the scenario `c` took) that follows another word after the
// command ("pierre run s.toml out": "out" after the scenario), or nullptr: a value given without
// its option.
const char* word_after_word(int argc, char** argv, const CLI::App& c) {
  std::string scenario;
  if (const CLI::Option* o = c.get_option_no_throw("scenario"); o && !o->results().empty())
    scenario = o->results().front();
  // After a flag (--strict, -q) or an option with its value attached (--throws=3), a word is
  // no option's value either.
  auto takes_next = [&c](std::string_view prev) {
    if (prev.empty() || prev[0] != '-' || prev.find('=') != std::string_view::npos) return false;
    const CLI::Option* o = c.get_option_no_throw(std::string(prev));
    return !o || o->get_items_expected_min() > 0;
  };
  for (int i = 3; i < argc; ++i) {
    if (std::string_view(argv[i]) == "--") break;
    if (argv[i][0] != '-' && !takes_next(argv[i - 1]) && argv[i] != scenario) return argv[i];
  }
  return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pierre::app;
  // A closed pipe is a failed write (EPIPE, exit 3 below), not a silent death by SIGPIPE (141).
  std::signal(SIGPIPE, SIG_IGN);
  try {
    CLI::App app{"pierre " PIERRE_VERSION
                 " — stochastic lumped-mass rockfall simulation (PIERRE 2) and protection design",
                 "pierre"};
    app.set_version_flag("--version", "pierre " + pierre::io::version_text());
    app.require_subcommand(1);
    app.footer(
        "Example:\n"
        "  pierre validate examples/vaujany-2d/scenario.toml\n"
        "  pierre run examples/vaujany-2d/scenario.toml --out results/vaujany --seed 42\n"
        "  pierre check examples/vaujany-2d/scenario.toml --out results/vaujany\n"
        "Run `pierre <command> --help` for a command's options. Exit codes: 0 ran (check: every\n"
        "check passed), 1 a check failed (check only, even when the standard output is lost),\n"
        "2 bad input or usage, 3 internal error or the standard output lost (a closed pipe:\n"
        "`pierre check ... | head -1` may give 3), 130 interrupted by Ctrl-C, SIGTERM or SIGHUP\n"
        "(nothing written).");

    std::vector<std::unique_ptr<Command>> commands;
    commands.push_back(make_run_command());
    commands.push_back(make_check_command());
    commands.push_back(make_validate_command());
    std::vector<CLI::App*> subs;
    for (auto& c : commands) subs.push_back(c->add_to(app));

    // `pierre help [command]`, as git and cargo take it: the help it names (what follows the
    // command is left out, as --help would ignore it).
    std::vector<char*> args(argv, argv + argc);
    std::string help_flag = "--help";
    if (argc >= 2 && std::string_view(argv[1]) == "help") {
      if (argc == 2) {
        args = {argv[0], help_flag.data()};
      } else if (is_command(argv[2], subs)) {
        args = {argv[0], argv[2], help_flag.data()};
      } else {
        std::fprintf(stderr, "pierre help: found %s, expected a command: run, check or validate\n",
                     argv[2]);
        return kExitInput;
      }
    }
    // --version after a command ("pierre run --version") is the program's: CLI11 knows it on
    // the program alone, and said "found no scenario".
    for (int i = 1; i < argc && std::string_view(argv[i]) != "--"; ++i)
      if (std::string_view(argv[i]) == "--version") {
        args = {argv[0], argv[i]};
        break;
      }
    argc = static_cast<int>(args.size());
    argv = args.data();
    // A long option typed with one dash ("-out x") would be read by CLI11 as short options
    // with a value ("-o ut"), and the run would go quietly to ./ut: refuse it and name it.
    std::vector<CLI::App*> apps = subs;
    apps.push_back(&app);
    if (const std::string word = single_dash_long_option(argc, argv, apps); !word.empty()) {
      std::fprintf(stderr, "pierre: found %s, expected -%s: long options take two dashes (pierre --help)\n",
                   word.c_str(), word.c_str());
      return kExitInput;
    }
    try {
      app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --help-all, --version
      app.exit(e);
      // Lost on its way (a full disk): a script reading the version must not take exit 0.
      if (std::fflush(stdout) != 0 || std::ferror(stdout)) return lost_stdout();
      return kExitOk;
    } catch (const CLI::ExtrasError& e) {
      // CLI11 lists the extra arguments back to front ("foo --out" for --out foo): name them in
      // the order they were typed, with the command they do not belong to.
      for (CLI::App* c : subs)
        if (c->parsed()) {
          std::vector<std::string> extra = c->remaining();
          // Words after "--" are left with the program, not the command.
          if (extra.empty()) extra = app.remaining();
          std::erase(extra, std::string("--"));
          std::string words;
          for (const auto& w : extra) words += (words.empty() ? "" : " ") + w;
          const char* name = c->get_name().c_str();
          if (!extra.empty() && extra.front().size() > 1 && extra.front()[0] == '-')
            std::fprintf(stderr, "pierre %s: found %s: %s is not an option of pierre %s%s (pierre %s --help)\n",
                         name, words.c_str(), extra.front().c_str(), name,
                         nearest_option_hint(*c, extra.front()).c_str(), name);
          else
            std::fprintf(stderr, "pierre %s: found %s, expected no more arguments (pierre %s --help)\n",
                         name, words.c_str(), name);
          return kExitInput;
        }
      app.exit(e);
      return kExitInput;
    } catch (const CLI::RequiredError& e) {
      // Said as every other error is (found, expected), with the command's help to read; CLI11
      // says "--out is required" (new-user review).
      const auto parsed = std::find_if(subs.begin(), subs.end(), [](CLI::App* c) { return c->parsed(); });
      // "pierre -- run": the command after "--" is a word, not a command (CLI11: "A subcommand
      // is required", said of the command it then half-took).
      if (parsed == subs.end() || std::string_view(e.what()).starts_with("A subcommand")) {
        if (argc >= 2 && argv[1][0] == '-' && std::string_view(argv[1]) != "--")  // "pierre -v"
          std::fprintf(stderr,
                       "pierre: found %s: not an option of pierre; expected a command (run, check "
                       "or validate), --help or --version (pierre --help)\n",
                       argv[1]);
        else if (!said_misspelt_command(argc, argv, subs))
          std::fprintf(stderr, "pierre: found no command, expected run, check or validate (pierre --help)\n");
        return kExitInput;
      }
      std::string what = e.what();
      if (const auto at = what.find(" is required"); at != std::string::npos) what.resize(at);
      const std::string expected = what == "--out"      ? "--out DIR, the folder the results go to"
                                   : what == "scenario" ? "the scenario file (TOML) to read"
                                                        : "a " + what;
      const char* name = (*parsed)->get_name().c_str();
      // `pierre run s.toml out`: the folder typed without its option.
      std::string hint;
      if (what == "--out")
        if (const char* w = word_after_word(argc, argv, **parsed))
          hint = fmt::format("; {} stands alone: did you mean --out {}?", w, w);
      std::fprintf(stderr, "pierre %s: found no %s, expected %s%s (pierre %s --help)\n", name,
                   what.c_str(), expected.c_str(), hint.c_str(), name);
      return kExitInput;
    } catch (const CLI::ParseError& e) {
      if (said_misspelt_command(argc, argv, subs)) return kExitInput;
      app.exit(e);
      return kExitInput;
    }
    for (std::size_t i = 0; i < commands.size(); ++i) {
      if (!subs[i]->parsed()) continue;
      const int code = commands[i]->run();
      // What the command printed must have reached stdout (a full disk, a closed pipe): else a
      // script reading it would take a lost verdict for a given one.
      // A FAIL stays 1 even then: the results are written, and a pipeline must see the verdict.
      if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
        const int lost = lost_stdout(subs[i]->get_name() != "validate");
        return code == kExitCheckFailed ? code : lost;
      }
      return code;
    }
    return kExitInput;
  } catch (const pierre::io::InputError& e) {
    std::fflush(stdout);
    std::fputs((std::string(e.what()) + "\n").c_str(), stderr);  // fputs never throws
    return kExitInput;
  } catch (const pierre::io::CommitError& e) {  // a result file held open, or not a file
    return said_as_input("cannot put the results in place: ", e);
  } catch (const pierre::app::RunOutOfMemory& e) {  // a run too large for the memory it has
    return said_as_input("", e);
  } catch (const pierre::io::OutputWriteError& e) {  // a full disk, a file size limit
    return said_as_input("", e);
  } catch (const std::exception& e) {
    // fmt throws when a print to stdout fails: that is the output's fault, said as such.
    if (std::fflush(stdout) != 0 || std::ferror(stdout)) return lost_stdout();
    std::fputs(("internal error: " + std::string(e.what()) + "\n").c_str(), stderr);
    return kExitInternal;
  } catch (...) {
    std::fputs("internal error: unknown exception\n", stderr);
    return kExitInternal;
  }
}
