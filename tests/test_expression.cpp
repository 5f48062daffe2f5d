// The page's expression evaluator (src/web/shim/expression.h) against Debian's muParser, the
// command-line program's: the oracle for "expr drives in the page give the CLI's values".
// A corpus of hand-written expressions (every operator, function, constant, precedence and
// associativity case, and malformed texts) and seeded random ones, valid and mutated, each
// compiled by both: the same accept/refuse decision, and where both accept, the same value at
// many t. Expected: the same double (natively both call glibc's functions on the same
// arguments in the same order, muParser's rewrites mirrored), NaN for NaN; the issue's bound
// is 1e-14 relative, checked as well and the largest difference printed.
#include <muParser.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "web/shim/expression.h"

namespace {

// What one side makes of a text: refused, or its values at kTimes.
struct Outcome {
  bool accepted = false;
  std::string message;
  std::vector<double> values;
};

const std::vector<double> kTimes = {
    0.0,   -0.0,   1e-300, 1e-3,  0.1,    0.25,  0.5,   1.0, 1.5,   2.0,  2.5,    3.0,   3.7,  4.0,
    7.25,  10.0,   19.99,  20.0,  33.3,   100.0, 250.5, 1e4, -1e-3, -0.5, -1.0,   -1.5,  -2.0, -3.3,
    -10.0, -100.0, 0.999,  1.001, 12.345, 1e8,   -1e8,  0.7, -0.7,  6.5,  0.0625, 1.0e-8};

// The drive's own setup (drive.cpp): variable t, constant pi.
Outcome with_muparser(const std::string& text) {
  Outcome out;
  double t = 0.0;
  try {
    mu::Parser p;
    p.DefineVar("t", &t);
    p.DefineConst("pi", std::numbers::pi);
    p.SetExpr(text);
    p.Eval();
    out.accepted = true;
    for (double v : kTimes) {
      t = v;
      out.values.push_back(p.Eval());
    }
  } catch (const mu::Parser::exception_type& e) {
    out.message = e.GetMsg();
  }
  return out;
}

Outcome with_ours(const std::string& text) {
  Outcome out;
  double t = 0.0;
  try {
    cb::expression::Expression p;
    p.define_variable("t", &t);
    p.define_constant("pi", std::numbers::pi);
    p.compile(text);
    p.evaluate();
    out.accepted = true;
    for (double v : kTimes) {
      t = v;
      out.values.push_back(p.evaluate());
    }
  } catch (const cb::expression::ExpressionError& e) {
    out.message = e.what();
  }
  return out;
}

// Written out by hand: what each construct must do, and texts that must be refused.
const std::vector<std::string> kHandWritten = {
    // numbers and constants
    "0", "1", "0.5", ".5", "5.", "1e3", "1E3", "1e+3", "1e-3", "1.5e2", "2.5E-2", "1e-400",
    "1e-310", "1e308", "123456789012345678901234567890", "0.1+0.2", "pi", "_pi", "_e", "2*pi*t",
    "_pi*t", "_e^t", "t", " t", "t ", "\tt\n", "  1  +  2  ",
    // arithmetic, precedence, associativity
    "1+2*3", "1+2*3-4/5", "8/4/2", "2-3-4", "2^3^2", "2^0.5^2", "(2^3)^2", "2*3^2", "-2^2", "-t^2",
    "(-t)^2", "-(t)^2", "2^-1", "2^-t", "2^+2", "2^-3^2", "2^-3*2", "-2^-2", "-3^2", "2*-3", "2--3",
    "2-+3", "1-(-2)", "1+ +2", "1*+2", "1*-2^2", "-t*2", "2/-t", "2*t^2", "t^-2", "+t", "+t*2",
    "-t", "- t", "-(t)", "-(-t)", "+2^2", "-2*3^2", "1+-2*3", "-t+1", "-1<2", "2^t^2", "t^t",
    "t^0.5", "(t+1)^(t-1)", "t^3^2",
    // the rewrites muParser makes (t*c+d, t^n), which change the rounding
    "t*2", "2*t", "t*t", "t*t*t", "t^0", "t^1", "t^2", "t^3", "t^4", "t^5", "t^2.5", "t^-1", "t+1",
    "1+t", "t-1", "1-t", "t+t", "t-t", "2*t+1", "2*t-1", "1+2*t", "3-2*t", "2*t/3", "t/3", "t/3*2",
    "(2*t+1)*3", "3*(2*t+1)", "(2*t+1)/7", "2*t+1+1", "2*t+t", "t+2*t", "2*t+3*t", "2*t-3*t",
    "t*0.1+0.2", "0.1*t+0.2*t+0.3", "(t-20)^2", "-0.04*(t-20)^2", "exp(-0.04*(t-20)^2)", "0.02*t",
    "sin(t/10)", "t*-2", "-2*t", "t*(1/3)", "(t+1)*(t+1)", "t*t+t", "t*2*2", "2*2*t", "2*(2*t)",
    "t/0", "(2*t)/0", "0*t", "t*0+1",
    // comparisons and logic
    "1<2", "2<1", "1>2", "1<=1", "1>=2", "1==1", "1!=1", "3!=3", "1<2<3", "3>2>1", "t<1", "t>1",
    "t<=1.5", "t>=1.5", "t==1.5", "t!=1.5", "1==1 && 2", "0||3", "1&&0||1", "1||0&&0", "0.5&&1",
    "0.5||0", "t&&1", "t||0", "t-1&&1", "(t-1)&&1", "t-1.4||0", "t<2&&t>-2", "t<0||t>2", "1+2<4",
    "1<2==1", "sin(1)&&1", "(1?0.5:0)&&1", "sum(0.5)&&1", "1e10&&1", "-1e10||0", "0&&1/0",
    // the ternary
    "1?2:3", "0?2:3", "t>1?t:-t", "t<1?0:t<2?1:2", "1?0?5:6:7", "1 ? 2 : 0 ? 3 : 4", "1+2?3:4",
    "0?1:2+10", "1<2?3:4", "1||0?5:6", "-1?2:3", "1 ? 2 : 3 , 4", "sum(1,2)?3:4", "(1)?2:3",
    "1?2:(3)", "(1?2:3)", "(1?2:3)+1", "(t<1?1:2)*t", "sum(1?2:3,4)", "t?1:0", "1?-2:-3",
    "1?2:-3^2", "t>2?exp(-t):t^2", "(t>1)*(t-1)", "2*(t>1?1:0)",
    // assignment and lists (muParser accepts them: t is a variable)
    "t=5", "t=5,t", "1+(t=2)", "(t=2)+t", "t=t+1", "t=-2", "t=(2)", "1?t=2:3", "t=1?2:3",
    "(t=1)?2:3", "sum(t=2,t)", "1,2", "1,2,3", "t,2*t",
    // functions
    "sin(t)", "cos(t)", "tan(t)", "asin(t/1e8)", "acos(t/1e8)", "atan(t)", "atan2(t,2)",
    "atan2(1,t)", "sinh(t/100)", "cosh(t/100)", "tanh(t)", "asinh(t)", "acosh(t)", "atanh(t/1e8)",
    "log2(t)", "log10(t)", "log(t)", "ln(t)", "log(_e)", "ln(10)", "exp(t)", "exp(-t)", "sqrt(t)",
    "sign(t)", "sign(0)", "sign(-2)", "rint(t)", "rint(2.5)", "rint(-2.5)", "abs(t)", "abs(-0)",
    "sum(t)", "sum(1,2,3)", "sum(t,t^2,t^3)", "avg(1,2,4)", "avg(t,1)", "min(3,1,2)", "min(t,1)",
    "max(t,1)", "max(1)", "min(-1,2)", "max(t,-t,0.5)", "sin(t)^2", "sin(t)^2+cos(t)^2", "sin((t))",
    "((((1))))", "sin(-(-t))", "-sin(t)", "sin(-t)", "sum(1,2)^2", "-sum(1,2)", "-sum(1,2)^2",
    "2^sum(1,2)", "2^sin(t)", "sin(cos(tan(t)))", "max(min(t,2),-2)", "sum(sin(t),cos(t),1)",
    "exp(log(t))", "sin(1)+cos(1)*tan(1)", "abs(-3)+sign(0)", "log10(1000)", "exp(1)", "sqrt(-1)",
    "log(0)", "1/0", "0/0", "-0", "1e308*10", "atan2(0,-1)", "sin(2*pi*t/120)",
    "0.5*(1+tanh((t-50)/5))", "t<10?0.1*t:1", "min(0.02*t,1)", "sin(t)*exp(-t/50)",
    // malformed: the same refusal
    "", " ", "\t", "--2", "-+2", "+-2", "1+-+2", "--t", "+", "-", "*2", "2*", "1+", "(1", "1)",
    "()", ")1", "(1,2)", "sum((1,2))", "1,", ",1", "sum(1,)", "sum(,1)", "sum()", "sin()",
    "sin(1,2)", "atan2(1)", "atan2(1,2,3)", "sum(1,2", "sin(", "2 3", "2t", "2 t", "t t", "1e",
    "1e+", "1e-", "1.5.3", "1.2e3.4", "1e3t", "t1", "t_", "_t", "t1e3", "_pi_e", "foo", "foo(1)",
    "e", "PI", "Pi", "pi2", "sin", "sin 1", "sin (t)", "sin ( t )", "pi(1)", "t(1)", "1(2)",
    "(1)(2)", "sin(1)(2)", "sin(1)2", "2sin(1)", "2(3)", "1&2", "1|2", "1 & 2", "a=2", "2=1",
    "2+t=3", "-t=3", "2*t=3", "t=2=3", "(t)=2", "1-t=2", "#", "1 ; 2", "1?2", "1:2", "?", "1??2:3",
    "1?:2", "1?2::3", "1?2,3:4", "1?(2,3):4", "inf", "nan", "1e400", "0x10", "1 2", "t..5", ".",
    ".e5", "1=", "=1", "!1", "1!", "1!=", "<1", "1<", "1<>2", "1=<2", "1=>2", "1 = = 1", "1&&",
    "||1", "1^^2", "2^", "^2", "t^", "sin)", "(", ")", "((1)", "(1))", "sum(1;2)", "min(1 2)",
    "max(,)", "abs(-)", "1+2)*(3", "t =", "= t", "é", "t²", "1,,2", "sum(1,,2)",
    // control characters: 1 to 13 are skipped as blanks, 14 to 31 refused (found by
    // fuzz_expression)
    "1+\x01"
    "2",
    "t\r", "\vt", "t\x0e", "\x17t",
    "1+\x1f"
    "2",
    "t\x7f"};

// A seeded generator of its own (splitmix64): the corpus is the same on every machine.
struct Random {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
};

std::string random_number(Random& r) {
  static const char* const kNumbers[] = {"0",   "1",   "2",    "3",   "0.5",  "10",   "1e-3",
                                         "2.5", "1e2", "0.04", ".25", "7.",   "1E-1", "20",
                                         "0.1", "4",   "1.5",  "120", "3e+1", "0.333"};
  return kNumbers[r.below(static_cast<int>(std::size(kNumbers)))];
}

std::string random_expression(Random& r, int depth) {
  if (depth <= 0 || r.below(5) == 0) {
    switch (r.below(6)) {
      case 0:
      case 1:
        return "t";
      case 2:
        return r.below(3) == 0 ? "pi" : r.below(2) ? "_pi" : "_e";
      default:
        return random_number(r);
    }
  }
  static const char* const kBinary[] = {"+", "-", "*",  "/",  "^",  "+",  "-",  "*",
                                        "<", ">", "<=", ">=", "==", "!=", "&&", "||"};
  static const char* const kUnary[] = {"sin",  "cos",  "tan",   "asin",  "acos",  "atan", "sinh",
                                       "cosh", "tanh", "asinh", "acosh", "atanh", "log2", "log10",
                                       "log",  "ln",   "exp",   "sqrt",  "sign",  "rint", "abs"};
  static const char* const kMany[] = {"sum", "avg", "min", "max"};
  const std::string space = r.below(4) == 0 ? " " : "";
  switch (r.below(10)) {
    case 0:
    case 1:
    case 2:
    case 3:
      return random_expression(r, depth - 1) + space + kBinary[r.below(16)] + space +
             random_expression(r, depth - 1);
    case 4: {
      // One sign only: muParser refuses --t (and so does the evaluator; the mutated texts and
      // the hand-written ones check that).
      const std::string operand = random_expression(r, depth - 1);
      const bool signed_operand = operand[0] == '-' || operand[0] == '+';
      return std::string(r.below(2) ? "-" : "+") + (signed_operand ? "(" + operand + ")" : operand);
    }
    case 5:
      return "(" + random_expression(r, depth - 1) + ")";
    case 6:
      return std::string(kUnary[r.below(21)]) + "(" + random_expression(r, depth - 1) + ")";
    case 7: {
      std::string out = std::string(kMany[r.below(4)]) + "(" + random_expression(r, depth - 1);
      for (int n = r.below(3); n > 0; --n) out += "," + space + random_expression(r, depth - 1);
      return out + ")";
    }
    case 8:
      return "atan2(" + random_expression(r, depth - 1) + "," + random_expression(r, depth - 1) +
             ")";
    default:
      return random_expression(r, depth - 1) + space + "?" + space +
             random_expression(r, depth - 1) + space + ":" + space +
             random_expression(r, depth - 1);
  }
}

// A valid text with one character deleted, doubled or replaced: mostly malformed.
std::string mutate(Random& r, std::string text) {
  static const std::string kChars = "+-*/^()?:,.<>=&|!t1e_ ";
  if (text.empty()) return text;
  const auto at = static_cast<std::size_t>(r.below(static_cast<int>(text.size())));
  switch (r.below(3)) {
    case 0:
      text.erase(at, 1);
      break;
    case 1:
      text.insert(at, 1, text[at]);
      break;
    default:
      text[at] = kChars[static_cast<std::size_t>(r.below(static_cast<int>(kChars.size())))];
  }
  return text;
}

bool same_double(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

// Relative difference, 0 for equal values and for NaN against NaN.
double relative_difference(double a, double b) {
  if (same_double(a, b)) return 0.0;
  if (std::isnan(a) || std::isnan(b) || std::isinf(a) || std::isinf(b)) return INFINITY;
  return std::fabs(a - b) / std::max(std::fabs(a), std::fabs(b));
}

struct Tally {
  int expressions = 0, accepted = 0, refused = 0, values = 0, exact = 0;
  double largest = 0.0;
};

void compare(const std::string& text, Tally& tally) {
  const Outcome reference = with_muparser(text);
  const Outcome ours = with_ours(text);
  ++tally.expressions;
  INFO("expression \"" << text << "\"; muParser: "
                       << (reference.accepted ? "accepted" : "refused: " + reference.message)
                       << "; ours: " << (ours.accepted ? "accepted" : "refused: " + ours.message));
  REQUIRE(ours.accepted == reference.accepted);
  if (!ours.accepted) {
    ++tally.refused;
    return;
  }
  ++tally.accepted;
  for (std::size_t i = 0; i < kTimes.size(); ++i) {
    const double a = ours.values[i], b = reference.values[i];
    INFO("t = " << kTimes[i] << ": ours " << a << ", muParser " << b);
    const double d = relative_difference(a, b);
    tally.largest = std::max(tally.largest, d);
    ++tally.values;
    if (same_double(a, b)) ++tally.exact;
    CHECK(d <= 1e-14);
    CHECK(same_double(a, b));
  }
}

}  // namespace

TEST_CASE("the page's expression evaluator agrees with muParser on the hand-written corpus",
          "[expression]") {
  Tally tally;
  for (const std::string& text : kHandWritten) compare(text, tally);
  std::printf(
      "hand-written: %d expressions (%d accepted, %d refused by both), %d values, %d "
      "the same double, largest relative difference %g\n",
      tally.expressions, tally.accepted, tally.refused, tally.values, tally.exact, tally.largest);
  CHECK(tally.expressions >= 200);
}

TEST_CASE("the page's expression evaluator agrees with muParser on random expressions",
          "[expression]") {
  Random r{20250125};
  Tally valid, mutated;
  for (int i = 0; i < 1500; ++i) {
    const std::string text = random_expression(r, 1 + r.below(5));
    compare(text, valid);
    compare(mutate(r, text), mutated);
  }
  std::printf(
      "random: %d valid expressions (%d values, %d the same double, largest relative "
      "difference %g); %d mutated ones (%d accepted, %d refused by both)\n",
      valid.expressions, valid.values, valid.exact, valid.largest, mutated.expressions,
      mutated.accepted, mutated.refused);
  CHECK(valid.accepted == valid.expressions);
  CHECK(mutated.refused > 500);
}

TEST_CASE("the evaluator's messages say what and where", "[expression]") {
  const auto message = [](const std::string& text) { return with_ours(text).message; };
  CHECK(message("2*") == "unexpected end of expression at position 2");
  CHECK(message("foo+1").find("unknown name \"foo\" at position 0") == 0);
  CHECK(message("sin (t)").find("needs its arguments in parentheses right after its name") !=
        std::string::npos);
  CHECK(message("atan2(1)") == "the function \"atan2\" at position 0 takes 2 arguments, not 1");
  CHECK(message("(1+2") == "the parenthesis opened at position 0 is never closed");
  CHECK(message("2t").find("unexpected \"t\" at position 1") == 0);
  CHECK(message("1e").find("\"1e\" at position 0 is not a number") == 0);
  CHECK(message("").find("the expression is empty") == 0);
}

TEST_CASE("the evaluator refuses an expression nested too deep, and evaluates one just below",
          "[expression]") {
  // A thousand '(' overflowed the recursive parser's stack (fuzz_expression under ASan). The
  // whole text is one level and each '(' opens another: below kMaxNesting levels the evaluator
  // gives muParser's values, past it a message.
  const int below = cb::expression::kMaxNesting - 1;
  const std::string deep = std::string(below, '(') + "t+1" + std::string(below, ')');
  const Outcome ours = with_ours(deep), reference = with_muparser(deep);
  REQUIRE(ours.accepted);
  REQUIRE(reference.accepted);
  CHECK(ours.values == reference.values);
  std::string powers = "2";
  for (int i = 0; i < 1000; ++i) powers += "^2";
  for (const std::string& text :
       {std::string(1000, '(') + "t" + std::string(1000, ')'), std::string(5000, '('), powers}) {
    const std::string message = with_ours(text).message;
    INFO(message);
    CHECK(message.find("the expression nests deeper than " +
                       std::to_string(cb::expression::kMaxNesting) + " levels") == 0);
  }
}
