// Always-on check framework for the Anisotropic_fairing tests.
//
// Unlike assert(), these checks are compiled in every build type. Each check
// increments a global pass or fail counter; failures print file:line, the
// message and the values involved with full precision (%.17g).
// AF_test::report() prints the final line "N passed, N failed" and returns the
// process exit code (0 iff nothing failed).
//
// Independent of include/CGAL/Anisotropic_fairing (test oracle).

#ifndef AF_TEST_SUPPORT_CHECK_H
#define AF_TEST_SUPPORT_CHECK_H

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace AF_test {

struct Check_counters
{
  long passed = 0;
  long failed = 0;
};

inline Check_counters& counters()
{
  static Check_counters c; // one instance per program (inline function => unique)
  return c;
}

inline bool record_check(bool ok)
{
  if(ok) ++counters().passed;
  else   ++counters().failed;
  return ok;
}

inline long checks_passed() { return counters().passed; }
inline long checks_failed() { return counters().failed; }

// Prints "N passed, N failed" alone on a line; returns 0 iff no check failed.
inline int report()
{
  std::fflush(stdout);
  std::printf("%ld passed, %ld failed\n", counters().passed, counters().failed);
  std::fflush(stdout);
  return counters().failed == 0 ? 0 : 1;
}

namespace detail {

inline bool check(bool cond, const char* file, int line, const char* expr, const std::string& msg)
{
  if(!record_check(cond))
    std::printf("%s:%d: CHECK FAILED: %s  [%s]\n", file, line, msg.c_str(), expr);
  return cond;
}

// |value - expected| <= tol (absolute). NaN never passes.
inline bool check_close(double value, double expected, double tol,
                        const char* file, int line, const std::string& what)
{
  const double err = std::fabs(value - expected);
  const bool ok = (err <= tol); // false for NaN
  if(!record_check(ok))
    std::printf("%s:%d: CHECK_CLOSE FAILED: %s: value %.17g, expected %.17g, |diff| %.17g > tol %.17g\n",
                file, line, what.c_str(), value, expected, err, tol);
  return ok;
}

// |value - expected| <= rtol * |expected|. NaN never passes.
inline bool check_rel(double value, double expected, double rtol,
                      const char* file, int line, const std::string& what)
{
  const double err = std::fabs(value - expected);
  const double bound = rtol * std::fabs(expected);
  const bool ok = (err <= bound);
  if(!record_check(ok))
    std::printf("%s:%d: CHECK_REL FAILED: %s: value %.17g, expected %.17g, rel diff %.17g > rtol %.17g\n",
                file, line, what.c_str(), value, expected,
                expected != 0 ? err / std::fabs(expected) : err, rtol);
  return ok;
}

} // namespace detail

// Accumulates max |x - ref| (or any non-negative error) over samples, remembering
// where it occurred. print() writes e.g.
//   "<label>: max |x - ref| over 1234 samples: 3.2e-16 (at <where>)"
class Max_error
{
public:
  explicit Max_error(std::string label = "max |x - ref|") : label_(std::move(label)) {}

  // Adds one sample with error |value - ref|.
  void add(double value, double ref, const std::string& where = std::string())
  { add_error(std::fabs(value - ref), where); }

  // Adds one sample whose error is already computed (NaN becomes +inf).
  void add_error(double err, const std::string& where = std::string())
  {
    if(std::isnan(err)) err = HUGE_VAL;
    ++count_;
    if(count_ == 1 || err > max_) { max_ = err; where_ = where; }
  }

  double value() const { return count_ == 0 ? 0.0 : max_; }
  long count() const { return count_; }
  const std::string& where() const { return where_; }
  const std::string& label() const { return label_; }

  void print() const
  {
    if(where_.empty())
      std::printf("%s over %ld samples: %.3g\n", label_.c_str(), count_, value());
    else
      std::printf("%s over %ld samples: %.3g (at %s)\n", label_.c_str(), count_, value(), where_.c_str());
  }

private:
  std::string label_;
  double max_ = 0.0;
  long count_ = 0;
  std::string where_;
};

} // namespace AF_test

#define AF_CHECK(cond, msg) \
  ::AF_test::detail::check(static_cast<bool>(cond), __FILE__, __LINE__, #cond, (msg))

#define AF_CHECK_CLOSE(value, expected, tol, what) \
  ::AF_test::detail::check_close(static_cast<double>(value), static_cast<double>(expected), \
                                 static_cast<double>(tol), __FILE__, __LINE__, (what))

#define AF_CHECK_REL(value, expected, rtol, what) \
  ::AF_test::detail::check_rel(static_cast<double>(value), static_cast<double>(expected), \
                               static_cast<double>(rtol), __FILE__, __LINE__, (what))

#endif // AF_TEST_SUPPORT_CHECK_H
