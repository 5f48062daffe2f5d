// The expression evaluator of expression.h: a recursive-descent parser that writes a postfix
// program, and the loop that runs it.
//
// Index: functions (what each name computes) · reading (characters to tokens) · the parser
// (one function per precedence level) · rewrites (constant folding, t*c+d) · evaluate().
#include "web/shim/expression.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace cb::expression {

namespace {

using Op = Expression::Op;
using Instruction = Expression::Instruction;

// ==== Functions ===========================================================================
// muParser 2.3.3's definitions (tests/test_expression.cpp checks each against the library):
// the inverse hyperbolic functions and log2 by their logarithm formulas, rint as floor(v + 0.5),
// abs keeping -0, min and max in std::min / std::max's order (what a NaN argument gives).

double f_sin(double v) {
  return std::sin(v);
}
double f_cos(double v) {
  return std::cos(v);
}
double f_tan(double v) {
  return std::tan(v);
}
double f_asin(double v) {
  return std::asin(v);
}
double f_acos(double v) {
  return std::acos(v);
}
double f_atan(double v) {
  return std::atan(v);
}
double f_atan2(double y, double x) {
  return std::atan2(y, x);
}
double f_sinh(double v) {
  return std::sinh(v);
}
double f_cosh(double v) {
  return std::cosh(v);
}
double f_tanh(double v) {
  return std::tanh(v);
}
double f_asinh(double v) {
  return std::log(v + std::sqrt(v * v + 1));
}
double f_acosh(double v) {
  return std::log(v + std::sqrt(v * v - 1));
}
double f_atanh(double v) {
  return 0.5 * std::log((1 + v) / (1 - v));
}
double f_log2(double v) {
  return std::log(v) / std::log(2.0);
}
double f_log10(double v) {
  return std::log10(v);
}
double f_ln(double v) {
  return std::log(v);
}
double f_exp(double v) {
  return std::exp(v);
}
double f_sqrt(double v) {
  return std::sqrt(v);
}
double f_sign(double v) {
  return v < 0 ? -1.0 : v > 0 ? 1.0 : 0.0;
}
double f_rint(double v) {
  return std::floor(v + 0.5);
}
double f_abs(double v) {
  return v >= 0 ? v : -v;
}

double f_sum(const double* a, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += a[i];
  return s;
}
double f_avg(const double* a, int n) {
  return f_sum(a, n) / static_cast<double>(n);
}
double f_min(const double* a, int n) {
  double m = a[0];
  for (int i = 0; i < n; ++i) m = std::min(m, a[i]);
  return m;
}
double f_max(const double* a, int n) {
  double m = a[0];
  for (int i = 0; i < n; ++i) m = std::max(m, a[i]);
  return m;
}

struct Function {
  const char* name;
  int arity;  // -1: one or more
  double (*fn1)(double);
  double (*fn2)(double, double);
  double (*fnN)(const double*, int);
};

constexpr Function kFunctions[] = {
    {"sin", 1, f_sin, nullptr, nullptr},     {"cos", 1, f_cos, nullptr, nullptr},
    {"tan", 1, f_tan, nullptr, nullptr},     {"asin", 1, f_asin, nullptr, nullptr},
    {"acos", 1, f_acos, nullptr, nullptr},   {"atan", 1, f_atan, nullptr, nullptr},
    {"atan2", 2, nullptr, f_atan2, nullptr}, {"sinh", 1, f_sinh, nullptr, nullptr},
    {"cosh", 1, f_cosh, nullptr, nullptr},   {"tanh", 1, f_tanh, nullptr, nullptr},
    {"asinh", 1, f_asinh, nullptr, nullptr}, {"acosh", 1, f_acosh, nullptr, nullptr},
    {"atanh", 1, f_atanh, nullptr, nullptr}, {"log2", 1, f_log2, nullptr, nullptr},
    {"log10", 1, f_log10, nullptr, nullptr}, {"log", 1, f_ln, nullptr, nullptr},
    {"ln", 1, f_ln, nullptr, nullptr},       {"exp", 1, f_exp, nullptr, nullptr},
    {"sqrt", 1, f_sqrt, nullptr, nullptr},   {"sign", 1, f_sign, nullptr, nullptr},
    {"rint", 1, f_rint, nullptr, nullptr},   {"abs", 1, f_abs, nullptr, nullptr},
    {"sum", -1, nullptr, nullptr, f_sum},    {"avg", -1, nullptr, nullptr, f_avg},
    {"min", -1, nullptr, nullptr, f_min},    {"max", -1, nullptr, nullptr, f_max},
};

const Function* find_function(const std::string& name) {
  for (const Function& f : kFunctions)
    if (name == f.name) return &f;
  return nullptr;
}

std::string function_names() {
  std::string out;
  for (const Function& f : kFunctions) out += (out.empty() ? "" : " ") + std::string(f.name);
  return out;
}

// muParser folds && and || of two constants through an int cast (0.5 && 1 is 0), while at run
// time a nonzero double is true (t && 1 is 1 at t = 0.5). A cast of NaN or of a value out of
// int's range gives INT_MIN on x86, which is true; written out here, since the cast itself is
// undefined behaviour.
bool folded_truth(double v) {
  if (!(std::fabs(v) < 2147483648.0)) return true;
  return std::trunc(v) != 0.0;
}

double apply_binary(Op op, double x, double y) {
  switch (op) {
    case Op::Add:
      return x + y;
    case Op::Sub:
      return x - y;
    case Op::Mul:
      return x * y;
    case Op::Div:
      return x / y;
    case Op::Pow:
      return std::pow(x, y);
    case Op::Less:
      return x < y;
    case Op::Greater:
      return x > y;
    case Op::LessEqual:
      return x <= y;
    case Op::GreaterEqual:
      return x >= y;
    case Op::Equal:
      return x == y;
    case Op::NotEqual:
      return x != y;
    case Op::And:
      return x != 0.0 && y != 0.0;
    case Op::Or:
      return x != 0.0 || y != 0.0;
    default:
      return 0.0;
  }
}

// ==== Reading =============================================================================

bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
bool digit(char c) {
  return c >= '0' && c <= '9';
}

// muParser skips every character from 1 to 32 (spaces, tabs, newlines; parse() has refused
// those from 14 to 31 already).
bool blank(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u >= 1 && u <= 32;
}

// The binary operators and punctuation, longest first where one is a prefix of another.
constexpr const char* kSymbols[] = {"<=", ">=", "!=", "==", "&&", "||", "<", ">", "+", "-",
                                    "*",  "/",  "^",  "=",  "(",  ")",  "?", ":", ","};

class Parser {
 public:
  Parser(const std::string& text, const std::vector<std::pair<std::string, double*>>& variables,
         const std::vector<std::pair<std::string, double>>& constants,
         std::vector<Instruction>& program)
      : text_(text), variables_(variables), constants_(constants), out_(program) {}

  // The whole text: items separated by commas, the value is the last one's. Returns the
  // deepest the evaluation stack gets.
  int parse() {
    // muParser refuses characters 14 to 31 anywhere (and skips 1 to 13 as it skips spaces).
    for (std::size_t i = 0; i < text_.size(); ++i) {
      const auto u = static_cast<unsigned char>(text_[i]);
      if (u >= 14 && u < 32)
        fail("a control character (code " + std::to_string(u) + ") at position " +
                 std::to_string(i) + "; an expression is printable text",
             i, text_.substr(i, 1));
    }
    skip_blanks();
    if (at_end()) fail("the expression is empty; write one in t, e.g. \"0.02*t\"", pos_, "");
    assignment();
    while (peek_symbol() == ",") {
      take(1);
      assignment();
    }
    if (!at_end()) unexpected();
    return max_depth_;
  }

 private:
  // ---- the characters ----
  bool at_end() const { return pos_ >= text_.size(); }
  void skip_blanks() {
    while (!at_end() && blank(text_[pos_])) ++pos_;
  }
  void take(std::size_t n) {
    pos_ += n;
    skip_blanks();
  }
  std::string peek_symbol() const {
    for (const char* s : kSymbols)
      if (text_.compare(pos_, std::strlen(s), s) == 0) return s;
    return "";
  }
  std::string peek_name() const {
    std::size_t end = pos_;
    while (end < text_.size() && name_char(text_[end])) ++end;
    return text_.substr(pos_, end - pos_);
  }
  // What is at pos_, as a message names it.
  std::string here() const {
    if (at_end()) return "";
    const std::string symbol = peek_symbol();
    if (!symbol.empty()) return symbol;
    const std::string name = peek_name();
    return name.empty() ? text_.substr(pos_, 1) : name;
  }

  [[noreturn]] void fail(const std::string& what, std::size_t at, const std::string& token) const {
    throw ExpressionError(what, static_cast<int>(at), token);
  }
  [[noreturn]] void unexpected() const {
    if (at_end()) fail("unexpected end of expression at position " + position(), pos_, "");
    const std::string token = here();
    std::string what = "unexpected \"" + token + "\" at position " + position();
    if (token == ")")
      what += " (a closing parenthesis without its opening one)";
    else if (token == ",")
      what += " (a comma separates the arguments of a function such as max(a, b))";
    else if (token == "=")
      what += " (compare with ==)";
    else if (token == "&" || token == "|")
      what += " (the logical operators are && and ||)";
    else if (name_char(token[0]) || token == ".")
      what += " (an operator is missing before it, e.g. 2*t rather than 2t)";
    fail(what, pos_, token);
  }
  std::string position() const { return std::to_string(pos_); }

  // ---- the program ----
  void push(const Instruction& in, int depth_change) {
    out_.push_back(in);
    depth_ += depth_change;
    max_depth_ = std::max(max_depth_, depth_);
  }
  static Instruction value_of(double v) {
    Instruction in;
    in.op = Op::Value;
    in.value = v;
    return in;
  }

  // ---- the grammar, lowest precedence first ----

  // One level deeper for the recursion that parses a nested expression, refused past
  // kMaxNesting levels.
  class Nested {
   public:
    explicit Nested(Parser& parser) : parser_(parser) {
      if (++parser_.nesting_ > kMaxNesting)
        parser_.fail("the expression nests deeper than " + std::to_string(kMaxNesting) +
                         " levels at position " + parser_.position() +
                         " (parentheses, functions, \"? :\" or \"^\")",
                     parser_.pos_, parser_.here());
    }
    ~Nested() { --parser_.nesting_; }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;

   private:
    Parser& parser_;
  };

  // v = a, where v is a defined variable written right before the '='.
  void assignment() {
    const Nested level(*this);
    const std::string name = peek_name();
    double* var = name.empty() ? nullptr : variable(name);
    if (var) {
      std::size_t after = pos_ + name.size();
      while (after < text_.size() && blank(text_[after])) ++after;
      if (after < text_.size() && text_[after] == '=' &&
          (after + 1 >= text_.size() || text_[after + 1] != '=')) {
        pos_ = after;
        take(1);
        ternary();
        Instruction in;
        in.op = Op::Assign;
        in.var = var;
        push(in, 0);
        return;
      }
    }
    ternary();
  }

  // c ? a : b
  void ternary() {
    logical_or();
    if (peek_symbol() != "?") return;
    const std::size_t question = pos_;
    take(1);
    const std::size_t jump_if_zero = out_.size();
    Instruction branch;
    branch.op = Op::JumpIfZero;
    push(branch, -1);
    const int depth = depth_;
    assignment();
    if (peek_symbol() != ":") {
      if (at_end())
        fail(
            "the \"?\" at position " + std::to_string(question) + " has no \":\" (write c ? a : b)",
            question, "?");
      unexpected();
    }
    take(1);
    const std::size_t jump = out_.size();
    branch.op = Op::Jump;
    push(branch, 0);
    out_[jump_if_zero].count = static_cast<int>(out_.size());
    depth_ = depth;
    assignment();
    out_[jump].count = static_cast<int>(out_.size());
  }

  void logical_or() {
    const std::size_t left = out_.size();
    logical_and();
    while (peek_symbol() == "||") {
      take(2);
      const std::size_t right = out_.size();
      logical_and();
      binary(Op::Or, left, right);
    }
  }

  void logical_and() {
    const std::size_t left = out_.size();
    comparison();
    while (peek_symbol() == "&&") {
      take(2);
      const std::size_t right = out_.size();
      comparison();
      binary(Op::And, left, right);
    }
  }

  void comparison() {
    const std::size_t left = out_.size();
    sum();
    for (;;) {
      const std::string s = peek_symbol();
      Op op;
      if (s == "<")
        op = Op::Less;
      else if (s == ">")
        op = Op::Greater;
      else if (s == "<=")
        op = Op::LessEqual;
      else if (s == ">=")
        op = Op::GreaterEqual;
      else if (s == "==")
        op = Op::Equal;
      else if (s == "!=")
        op = Op::NotEqual;
      else
        return;
      take(s.size());
      const std::size_t right = out_.size();
      sum();
      binary(op, left, right);
    }
  }

  void sum() {
    const std::size_t left = out_.size();
    product();
    for (;;) {
      const std::string s = peek_symbol();
      if (s != "+" && s != "-") return;
      take(1);
      const std::size_t right = out_.size();
      product();
      binary(s == "+" ? Op::Add : Op::Sub, left, right);
    }
  }

  void product() {
    const std::size_t left = out_.size();
    sign();
    for (;;) {
      const std::string s = peek_symbol();
      if (s != "*" && s != "/") return;
      take(1);
      const std::size_t right = out_.size();
      sign();
      binary(s == "*" ? Op::Mul : Op::Div, left, right);
    }
  }

  // -a or +a: looser than ^, and one sign only (muParser refuses --2 and 1+-+2).
  void sign() {
    const std::string s = peek_symbol();
    if (s != "-" && s != "+") {
      power();
      return;
    }
    take(1);
    const std::string next = peek_symbol();
    if (next == "-" || next == "+") unexpected();
    const std::size_t start = out_.size();
    power();
    if (s == "+") return;  // muParser drops a unary plus
    if (out_.size() - start == 1 && out_.back().op == Op::Value) {
      out_.back().value = -out_.back().value;
      return;
    }
    Instruction in;
    in.op = Op::Negate;
    push(in, 0);
  }

  // a ^ b, right-associative; the exponent may carry a sign (2^-t).
  void power() {
    const std::size_t left = out_.size();
    primary();
    if (peek_symbol() != "^") return;
    take(1);
    const std::size_t right = out_.size();
    const Nested level(*this);  // the exponent: 2^2^2... recurses here
    sign();
    binary(Op::Pow, left, right);
  }

  void primary() {
    if (at_end()) unexpected();
    const char c = text_[pos_];
    if (digit(c) || c == '.') {
      number();
      return;
    }
    if (name_char(c)) {
      name();
      return;
    }
    if (peek_symbol() == "(") {
      const std::size_t open = pos_;
      take(1);
      assignment();
      if (peek_symbol() == ",")
        fail("a comma at position " + position() +
                 " inside parentheses that belong to no function (write e.g. max(a, b))",
             pos_, ",");
      close(open);
      return;
    }
    unexpected();
  }

  void close(std::size_t open) {
    if (peek_symbol() == ")") {
      take(1);
      return;
    }
    if (at_end())
      fail("the parenthesis opened at position " + std::to_string(open) + " is never closed", open,
           "(");
    unexpected();
  }

  // A number as muParser reads one (C++ stream extraction): digits, an optional fraction and an
  // optional exponent with at least one digit; a number too large for a double is refused, one
  // too small reads as 0 or a subnormal.
  void number() {
    const std::size_t start = pos_;
    std::size_t i = pos_;
    bool mantissa = false;
    while (i < text_.size() && digit(text_[i])) ++i, mantissa = true;
    if (i < text_.size() && text_[i] == '.') {
      ++i;
      while (i < text_.size() && digit(text_[i])) ++i, mantissa = true;
    }
    bool complete = mantissa;
    if (mantissa && i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      ++i;
      if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) ++i;
      complete = false;
      while (i < text_.size() && digit(text_[i])) ++i, complete = true;
    }
    const std::string literal = text_.substr(start, i - start);
    double v = 0.0;
    if (complete) {
      errno = 0;
      v = std::strtod(literal.c_str(), nullptr);
      if (errno == ERANGE && std::isinf(v)) complete = false;
    }
    if (!complete) {
      std::size_t end = i;
      while (end < text_.size() && name_char(text_[end])) ++end;
      const std::string token = text_.substr(start, end - start);
      fail("\"" + token + "\" at position " + std::to_string(start) +
               " is not a number (write e.g. 0.5, 2e-3 or 1.5E+2; at most about 1.8e308)",
           start, token);
    }
    pos_ = i;
    skip_blanks();
    push(value_of(v), 1);
  }

  double* variable(const std::string& name) const {
    for (const auto& [n, p] : variables_)
      if (n == name) return p;
    return nullptr;
  }

  void name() {
    const std::size_t start = pos_;
    const std::string id = peek_name();
    const bool call = start + id.size() < text_.size() && text_[start + id.size()] == '(';
    if (const Function* f = find_function(id); f && call) {
      function(*f, start);
      return;
    }
    double* var = variable(id);
    const auto constant = std::find_if(constants_.begin(), constants_.end(),
                                       [&](const auto& c) { return c.first == id; });
    if (var || constant != constants_.end()) {
      pos_ += id.size();
      skip_blanks();
      if (var) {
        Instruction in;
        in.op = Op::Variable;
        in.var = var;
        push(in, 1);
      } else {
        push(value_of(constant->second), 1);
      }
      if (peek_symbol() == "(")
        fail("\"" + id + "\" at position " + std::to_string(start) +
                 " is not a function; it takes no parentheses",
             start, id);
      return;
    }
    if (find_function(id))
      fail("the function \"" + id + "\" at position " + std::to_string(start) +
               " needs its arguments in parentheses right after its name, e.g. " + id + "(t)",
           start, id);
    std::string known;
    for (const auto& [n, p] : variables_) known += " " + n;
    for (const auto& [n, v] : constants_) known += " " + n;
    fail("unknown name \"" + id + "\" at position " + std::to_string(start) + " (the names are" +
             known + " and the functions " + function_names() + ")",
         start, id);
  }

  void function(const Function& f, std::size_t start) {
    pos_ += std::strlen(f.name);
    const std::size_t open = pos_;
    take(1);
    int count = 0;
    std::vector<std::size_t> starts;
    if (peek_symbol() != ")") {
      for (;;) {
        starts.push_back(out_.size());
        assignment();
        ++count;
        if (peek_symbol() != ",") break;
        take(1);
      }
    }
    const std::string arguments = f.arity < 0    ? "one or more arguments"
                                  : f.arity == 1 ? "one argument"
                                                 : std::to_string(f.arity) + " arguments";
    if (count < std::max(f.arity, 1) || (f.arity > 0 && count > f.arity)) {
      if (peek_symbol() != ")") close(open);  // reports a text cut short first
      fail(std::string("the function \"") + f.name + "\" at position " + std::to_string(start) +
               " takes " + arguments + ", not " + std::to_string(count),
           start, f.name);
    }
    close(open);
    // muParser computes a function of constants once, at compile time (not sum, avg, min, max).
    bool constant = f.arity > 0;
    for (int i = 0; i < count && constant; ++i)
      constant = out_.size() - starts[i] == static_cast<std::size_t>(count - i) &&
                 out_[starts[i]].op == Op::Value;
    Instruction in;
    if (constant) {
      const double v = f.arity == 1 ? f.fn1(out_[starts[0]].value)
                                    : f.fn2(out_[starts[0]].value, out_[starts[1]].value);
      out_.resize(starts[0]);
      depth_ -= count;
      push(value_of(v), 1);
      return;
    }
    if (f.arity == 1) {
      in.op = Op::Call1;
      in.fn1 = f.fn1;
    } else if (f.arity == 2) {
      in.op = Op::Call2;
      in.fn2 = f.fn2;
    } else {
      in.op = Op::CallN;
      in.fnN = f.fnN;
      in.count = count;
    }
    push(in, 1 - count);
  }

  // ==== Rewrites ==========================================================================
  // muParser rewrites an operation whose two operands are single operations as the program is
  // written, and its values are those of the rewritten form (2*t/3 is t*(2/3)+0, t^3 is t*t*t),
  // so the same rewrites are made here. `left` and `right` are where each operand's operations
  // start; each rewrite needs both operands to be one operation.
  void binary(Op op, std::size_t left, std::size_t right) {
    const bool single = out_.size() - right == 1 && right - left == 1;
    if (single && rewrite(op, out_[left], out_[right])) {
      out_.pop_back();
      --depth_;
      return;
    }
    Instruction in;
    in.op = op;
    push(in, -1);
  }

  // A single operation as muParser's t*mul + value form: a constant is 0*t + v, t is 1*t + 0.
  static bool linear(const Instruction& in) {
    return in.op == Op::Value || in.op == Op::Variable || in.op == Op::VarMul;
  }
  static double mul_of(const Instruction& in) {
    return in.op == Op::Value ? 0.0 : in.op == Op::Variable ? 1.0 : in.mul;
  }
  static double value_of_form(const Instruction& in) {
    return in.op == Op::VarMul || in.op == Op::Value ? in.value : 0.0;
  }

  // Rewrites a (op) b into a, true when it does.
  static bool rewrite(Op op, Instruction& a, const Instruction& b) {
    if (a.op == Op::Value && b.op == Op::Value) {
      if (op == Op::And)
        a.value = folded_truth(a.value) && folded_truth(b.value);
      else if (op == Op::Or)
        a.value = folded_truth(a.value) || folded_truth(b.value);
      else
        a.value = apply_binary(op, a.value, b.value);
      return true;
    }
    const bool same_var = a.var && b.var && a.var == b.var;
    switch (op) {
      case Op::Pow:
        if (a.op != Op::Variable || b.op != Op::Value) return false;
        if (b.value == 0) {
          a = value_of(1.0);
        } else if (b.value == 1) {
          // t^1 is t
        } else if (b.value == 2) {
          a.op = Op::VarPow2;
        } else if (b.value == 3) {
          a.op = Op::VarPow3;
        } else if (b.value == 4) {
          a.op = Op::VarPow4;
        } else {
          return false;
        }
        return true;
      case Op::Add:
      case Op::Sub: {
        if (!linear(a) || !linear(b)) return false;
        const bool one_constant = (a.op == Op::Value) != (b.op == Op::Value);
        if (!one_constant && !(a.op != Op::Value && same_var)) return false;
        const double s = op == Op::Sub ? -1.0 : 1.0;
        const double mul = mul_of(a) + s * mul_of(b);
        const double value = value_of_form(a) + s * value_of_form(b);
        a.var = a.var ? a.var : b.var;
        a.op = Op::VarMul;
        a.mul = mul;
        a.value = value;
        return true;
      }
      case Op::Mul:
        if ((a.op == Op::Variable && b.op == Op::Value) ||
            (a.op == Op::Value && b.op == Op::Variable)) {
          // muParser adds the constant to the variable's offset of 0.
          a.mul = value_of_form(a) + value_of_form(b);
          a.value = 0.0;
          a.var = a.var ? a.var : b.var;
          a.op = Op::VarMul;
          return true;
        }
        if (a.op == Op::VarMul && b.op == Op::Value) {
          a.mul *= b.value;
          a.value *= b.value;
          return true;
        }
        if (a.op == Op::Value && b.op == Op::VarMul) {
          const double c = a.value;
          a = b;
          a.mul = b.mul * c;
          a.value = b.value * c;
          return true;
        }
        if (a.op == Op::Variable && b.op == Op::Variable && same_var) {
          a.op = Op::VarPow2;
          return true;
        }
        return false;
      case Op::Div:
        if (a.op == Op::VarMul && b.op == Op::Value && b.value != 0) {
          a.mul /= b.value;
          a.value /= b.value;
          return true;
        }
        return false;
      default:
        return false;
    }
  }

  const std::string& text_;
  const std::vector<std::pair<std::string, double*>>& variables_;
  const std::vector<std::pair<std::string, double>>& constants_;
  std::vector<Instruction>& out_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  int max_depth_ = 0;
  int nesting_ = 0;  // Nested levels open
};

}  // namespace

void Expression::define_variable(const std::string& name, double* value) {
  variables_.emplace_back(name, value);
}

void Expression::define_constant(const std::string& name, double value) {
  constants_.emplace_back(name, value);
}

void Expression::compile(const std::string& text) {
  std::vector<Instruction> program;
  std::vector<std::pair<std::string, double>> constants = {{"_pi", 3.141592653589},
                                                           {"_e", 2.718281828459045235360287}};
  constants.insert(constants.end(), constants_.begin(), constants_.end());
  const int depth = Parser(text, variables_, constants, program).parse();
  text_ = text;
  program_ = std::move(program);
  stack_.assign(static_cast<std::size_t>(std::max(depth, 1)), 0.0);
}

// ==== evaluate() ============================================================================
double Expression::evaluate() const {
  if (program_.empty()) return std::nan("");  // compile() has not succeeded
  double* const base = stack_.data();
  double* top = base - 1;  // the last value pushed
  const Instruction* const program = program_.data();
  const std::size_t size = program_.size();
  for (std::size_t i = 0; i < size; ++i) {
    const Instruction& in = program[i];
    switch (in.op) {
      case Op::Value:
        *++top = in.value;
        break;
      case Op::Variable:
        *++top = *in.var;
        break;
      case Op::VarMul:
        *++top = *in.var * in.mul + in.value;
        break;
      case Op::VarPow2: {
        const double v = *in.var;
        *++top = v * v;
        break;
      }
      case Op::VarPow3: {
        const double v = *in.var;
        *++top = v * v * v;
        break;
      }
      case Op::VarPow4: {
        const double v = *in.var;
        *++top = v * v * v * v;
        break;
      }
      case Op::Negate:
        *top = -*top;
        break;
      case Op::Add:
      case Op::Sub:
      case Op::Mul:
      case Op::Div:
      case Op::Pow:
      case Op::Less:
      case Op::Greater:
      case Op::LessEqual:
      case Op::GreaterEqual:
      case Op::Equal:
      case Op::NotEqual:
      case Op::And:
      case Op::Or:
        --top;
        *top = apply_binary(in.op, top[0], top[1]);
        break;
      case Op::Call1:
        *top = in.fn1(*top);
        break;
      case Op::Call2:
        --top;
        *top = in.fn2(top[0], top[1]);
        break;
      case Op::CallN:
        top -= in.count - 1;
        *top = in.fnN(top, in.count);
        break;
      case Op::JumpIfZero:
        if (*top-- == 0.0) i = static_cast<std::size_t>(in.count) - 1;
        break;
      case Op::Jump:
        i = static_cast<std::size_t>(in.count) - 1;
        break;
      case Op::Assign:
        *in.var = *top;
        break;
    }
  }
  return *top;
}

}  // namespace cb::expression
