#pragma once
// One definition of pi for core/ and calib/: M_PI is POSIX, not C++17, and eight files
// had each written their own.

namespace omnitune {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace omnitune
