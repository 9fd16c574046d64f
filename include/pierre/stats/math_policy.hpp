// The Boost.Math policy every distribution in pierre::stats uses.
//  - Boost.Math throws on a domain error by default; the core throws nothing for ordinary
//    bad data, so domain errors return NaN and overflows return infinity instead.
//  - No promotion of double to long double inside the special functions: long double is
//    80-bit on x86-64 and 128-bit software on AArch64, so promotion would make results
//    (and speed) differ between platforms; double keeps them alike and fast.
#pragma once

#include <boost/math/policies/policy.hpp>

namespace pierre::stats {

namespace bmp = boost::math::policies;

using MathPolicy =
    bmp::policy<bmp::domain_error<bmp::ignore_error>, bmp::pole_error<bmp::ignore_error>,
                bmp::overflow_error<bmp::ignore_error>, bmp::evaluation_error<bmp::ignore_error>,
                bmp::indeterminate_result_error<bmp::ignore_error>, bmp::promote_float<false>,
                bmp::promote_double<false>>;

}  // namespace pierre::stats
