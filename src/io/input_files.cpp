#include "pierre/io/input_files.hpp"

#include <algorithm>
#include <cstdint>

#include <nettle/sha2.h>

namespace pierre::io {
namespace {
thread_local InputFilesRecord* active = nullptr;
}  // namespace

InputFilesRecord::InputFilesRecord() : outer_(active) { active = this; }
InputFilesRecord::~InputFilesRecord() { active = outer_; }

void InputFilesRecord::note(const std::filesystem::path& file, const std::string& text) {
  if (!active) return;
  auto& files = active->files_;
  if (std::any_of(files.begin(), files.end(), [&](const InputFile& f) { return f.file == file; }))
    return;  // a rule set shared by two barriers: once
  files.push_back(input_file(file, text));
}

std::string sha256_hex(const std::string& bytes) {
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, bytes.size(), reinterpret_cast<const std::uint8_t*>(bytes.data()));
  std::uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&ctx, SHA256_DIGEST_SIZE, digest);
  constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (const std::uint8_t b : digest) {
    hex += kHex[b >> 4];
    hex += kHex[b & 0xF];
  }
  return hex;
}

InputFile input_file(const std::filesystem::path& file, const std::string& text) {
  return {file, sha256_hex(text), text.size()};
}

}  // namespace pierre::io
