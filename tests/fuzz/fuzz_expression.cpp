// The page's expression evaluator (src/web/shim/expression.h) against Debian's muParser, the
// program's: a differential harness. Both compile the text with the drive's names (t, pi);
// they must accept and refuse alike, and where both accept give the same double at a few t
// (natively both call glibc's functions in the same order; tests/test_expression.cpp is the
// fixed corpus). muParser is not instrumented; the evaluator is, so coverage steers by it.
#include <muParser.h>

#include <cctype>
#include <cmath>
#include <numbers>

#include "fuzz_support.h"
#include "web/shim/expression.h"

namespace {

// Texts where muParser, once a comma has been read, lets through what it cannot evaluate and
// gives what its stack holds: a sign at the very end ("1,-" is -1, "1,2,-" is 0, "1,t*-" is
// -t), a '?' right after a comma ("1,?2:3" is 0), or a sign with no operand of its own right
// before a '?' ("1,t*- ?3:4" is -t, "1,t-(- ?3:4)" is 3; found by this harness in CI, session
// 14; without a comma muParser refuses it) or before a ':' ("t>540,-0-t ?+ :1", found by this
// harness in session 20's CI run). Its defect; the evaluator refuses all of them, the one place
// where they part on purpose.
bool muparser_defect(const std::string& text) {
  const auto blank = [](char c) { return static_cast<unsigned char>(c) <= 32; };
  const auto sign = [](char c) { return c == '-' || c == '+'; };
  // Whether c ends an operand (a number, a name, a closing parenthesis): a sign after it is
  // binary, anywhere else unary.
  const auto ends_operand = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == ')';
  };
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) return false;
  std::size_t end = text.size();
  while (end > 0 && blank(text[end - 1])) --end;
  if (end > comma && sign(text[end - 1])) return true;
  for (std::size_t i = comma; i < text.size(); ++i) {
    if (text[i] != ',' && !sign(text[i])) continue;
    std::size_t j = i + 1;
    while (j < text.size() && blank(text[j])) ++j;
    if (j >= text.size() || (text[j] != '?' && text[j] != ':')) continue;
    if (text[i] == ',') return true;
    std::size_t k = i;
    while (k > 0 && blank(text[k - 1])) --k;
    if (k > 0 && !ends_operand(text[k - 1])) return true;
  }
  return false;
}

// Texts that may nest deeper than the evaluator's kMaxNesting, which it refuses on purpose and
// muParser does not: each level opens with a '(', a '^' or a '?'.
bool may_nest_too_deep(const std::string& text) {
  std::size_t openers = 0;
  for (const char c : text) openers += c == '(' || c == '^' || c == '?';
  return openers >= static_cast<std::size_t>(cb::expression::kMaxNesting);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = cb::fuzz::text_of(data, size);
  if (text.find('\0') != std::string::npos) return 0;  // muParser reads a C string
  if (muparser_defect(text)) return 0;
  double t_ours = 0.0, t_mu = 0.0;
  cb::expression::Expression ours;
  ours.define_variable("t", &t_ours);
  ours.define_constant("pi", std::numbers::pi);
  bool ours_accepts = true;
  try {
    ours.compile(text);
  } catch (const cb::expression::ExpressionError&) {
    ours_accepts = false;
  }
  // Past that depth only the evaluator: it must refuse or accept without overflowing its stack.
  if (may_nest_too_deep(text)) return 0;
  mu::Parser mu;
  bool mu_accepts = true;
  try {
    mu.DefineVar("t", &t_mu);
    mu.DefineConst("pi", std::numbers::pi);
    mu.SetExpr(text);
    mu.Eval();
  } catch (const mu::Parser::exception_type&) {
    mu_accepts = false;
  }
  FUZZ_CHECK(ours_accepts == mu_accepts);
  if (!ours_accepts || !mu_accepts) return 0;
  for (const double t : {0.0, 0.5, 1.5, -2.0, 37.25}) {
    t_ours = t_mu = t;
    const double a = ours.evaluate(), b = mu.Eval();
    FUZZ_CHECK((std::isnan(a) && std::isnan(b)) || a == b);
  }
  return 0;
}
