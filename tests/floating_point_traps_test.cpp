#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <csignal>
#include <sys/wait.h>

#include "harness/floating_point_traps.h"

namespace mfz {
namespace {

// Volatile, so that the compiler leaves the operation to run time.
double quotient(double x, double y) {
  volatile double a = x, b = y;
  return a / b;
}

// Killed by SIGFPE, or stopped by the handler a sanitizer puts on it (the
// clang build's UBSan reports "FPE" and exits 1). A trap that does not fire
// lets the statement finish, which a death test counts as a failure.
bool stopped_by_the_trap(int status) {
  return (WIFSIGNALED(status) && WTERMSIG(status) == SIGFPE) || (WIFEXITED(status) && WEXITSTATUS(status) != 0);
}

TEST(FloatingPointTraps, AnInvalidOperationInsideRaisesSigfpe) {
  EXPECT_EXIT(
      {
        const FloatingPointTraps traps;
        std::printf("%g\n", quotient(0.0, 0.0));
      },
      stopped_by_the_trap, "");
}

TEST(FloatingPointTraps, ADivisionByZeroInsideRaisesSigfpe) {
  EXPECT_EXIT(
      {
        const FloatingPointTraps traps;
        std::printf("%g\n", quotient(1.0, 0.0));
      },
      stopped_by_the_trap, "");
}

TEST(FloatingPointTraps, OverflowAndInexactResultsGoOnAsBefore) {
  const FloatingPointTraps traps;
  EXPECT_EQ(quotient(1e308, 1e-308), INFINITY);
  EXPECT_EQ(quotient(1.0, 3.0), 1.0 / 3.0);
}

TEST(FloatingPointTraps, TheStateBeforeIsBackWhenTheScopeEnds) {
  const int enabled_before = fegetexcept();
  { const FloatingPointTraps traps; }
  EXPECT_EQ(fegetexcept(), enabled_before);
  EXPECT_TRUE(std::isnan(quotient(0.0, 0.0)));
  EXPECT_TRUE(std::fetestexcept(FE_INVALID));
  std::feclearexcept(FE_ALL_EXCEPT);
}

}  // namespace
}  // namespace mfz
