// Elementary functions that give the same bits on every machine, compiler and C library, for
// what must not depend on them: a flawed chain's drawn thresholds (threshold_draw.h, issue #23).
//
// Design note: libm's log, exp, pow, log1p and erfc are only faithful, so their last bit is the
// library's choice, and glibc even picks its code by the CPU: glibc 2.36's pow on a CPU without
// FMA differs from the FMA build in 1 of ~1300 Weibull draws, which moved a threshold of 2.5 %
// of the shipped flawed chain's seeds by 1-3 ulps (session 28; musl in the page's wasm is a
// third library). These are built from IEEE's +, -, x, / alone, each correctly rounded
// everywhere (-ffp-contract=off, CMakeLists.txt: no fused multiply-add), and exact scalings by
// powers of two. Accuracy: about 1 ulp (log, log1p, exp), a few ulps (erfc),
// checked against the long double libm (tests/test_portable_math.cpp).
#pragma once

namespace cb::portable {

// a + b as an unevaluated pair hi + lo (|lo| <= ulp(hi) / 2): more than double precision
// where a quantity's rounding would cost accuracy (ln x near -37, -x^2 near -700).
struct Pair {
  double hi = 0.0, lo = 0.0;
};

double log(double x);            // ln x; -inf at 0, NaN below
double log1p(double x);          // ln(1 + x), accurate for small x; x > -1
double exp(double x);            // e^x
Pair times(double a, double b);  // a b exactly (Dekker's product, no FMA)
double erfc(double x);           // the complementary error function

}  // namespace cb::portable
