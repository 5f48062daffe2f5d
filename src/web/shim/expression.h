// The project's own evaluator of muParser's expression language, for the page's build: Debian
// ships muParser as a compiled x86-64 library only, and the project may not carry a copy of its
// sources, so shim/muParser.h puts this class behind the subset of mu::Parser that drive.cpp
// calls. The command-line program keeps Debian's muParser; tests/test_expression.cpp compares
// the two on a corpus of expressions (the oracle), natively.
//
// Design note: the language is muParser 2.3.3's default grammar as it behaves (probed against
// the library, not read from its sources), lowest precedence first:
//   a, b          a list: every item is evaluated, the value is the last (top level only)
//   v = a         assignment to a defined variable (a variable token right before '=')
//   c ? a : b     right-associative; only the branch taken is evaluated
//   ||   &&       logical, 1 or 0; a nonzero double is true
//   < > <= >= == !=   comparisons, 1 or 0, left-associative
//   + -   * /     left-associative
//   -a  +a        signs bind looser than ^ (-2^2 = -4) and not twice (--2 is refused)
//   a ^ b         right-associative (2^3^2 = 512); the exponent may carry a sign (2^-1)
//   functions     sin cos tan asin acos atan atan2 sinh cosh tanh asinh acosh atanh log2 log10
//                 log (= ln) ln exp sqrt sign rint abs, and sum avg min max of one or more
//                 arguments; the '(' follows the name with no space between
//   constants     _pi (3.141592653589, muParser's GCC value), _e, and those defined
// The value of each operation is the double muParser computes: the same libm function on the
// same arguments in the same order, including its compile-time rewrites (constants folded, and
// t*c+d, t^2, t^3, t^4 kept as one operation evaluated as muParser does). With Emscripten's
// musl instead of glibc a function may differ in the last bit; + - * / never do.
//
// SetExpr-time work: the text is parsed once into a flat postfix program; evaluate() runs it on
// a preallocated stack, so an RK4 stage costs a short loop and no allocation.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cb::expression {

// A text that is not an expression: what is wrong, where (0-based, as muParser counts), and
// the piece of text it is about.
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(const std::string& message, int position, std::string token)
      : std::runtime_error(message), position_(position), token_(std::move(token)) {}
  int position() const { return position_; }
  const std::string& token() const { return token_; }

 private:
  int position_;
  std::string token_;
};

// The deepest an expression may nest (parentheses, function calls, "? :" branches, chains of
// "^"): the parser is recursive, and a text of a thousand '(' overflowed its stack (found by
// fuzz_expression under ASan; the page's WebAssembly stack is smaller still). muParser has no
// such limit; no drive needs a tenth of it.
inline constexpr int kMaxNesting = 200;

class Expression {
 public:
  // The variable is read (and an assignment writes it) through the pointer at every
  // evaluate(): it must outlive this object.
  void define_variable(const std::string& name, double* value);
  void define_constant(const std::string& name, double value);
  // Parses `text` with the names defined so far. Throws ExpressionError.
  void compile(const std::string& text);
  // The value at the variables' current values. compile() must have succeeded.
  double evaluate() const;
  const std::string& text() const { return text_; }

  // One operation of the postfix program (public for the parser in expression.cpp).
  enum class Op : std::uint8_t {
    Value,     // push value
    Variable,  // push *var
    VarMul,    // push *var * mul + value (muParser's rewrite of c*t+d)
    VarPow2,   // push t*t
    VarPow3,   // push t*t*t
    VarPow4,   // push t*t*t*t
    Negate,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Less,
    Greater,
    LessEqual,
    GreaterEqual,
    Equal,
    NotEqual,
    And,
    Or,
    Call1,       // fn1 on the top
    Call2,       // fn2 on the top two
    CallN,       // fnN on the top `count`
    JumpIfZero,  // pop; if it is 0 go to `count`
    Jump,        // go to `count`
    Assign,      // *var = top (the top stays)
  };
  struct Instruction {
    Op op = Op::Value;
    int count = 0;  // CallN: arguments; JumpIfZero, Jump: the target
    double* var = nullptr;
    double mul = 0.0;
    double value = 0.0;
    double (*fn1)(double) = nullptr;
    double (*fn2)(double, double) = nullptr;
    double (*fnN)(const double*, int) = nullptr;
  };

 private:
  std::vector<std::pair<std::string, double*>> variables_;
  std::vector<std::pair<std::string, double>> constants_;
  std::string text_;
  std::vector<Instruction> program_;
  mutable std::vector<double> stack_;  // evaluate()'s, sized by compile()
};

}  // namespace cb::expression
