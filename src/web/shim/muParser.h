// Stands in for muParser in the page's build: Debian ships muParser as a compiled x86-64
// library only, and the page may not carry a copy of its sources. drive.cpp compiles unchanged
// against this header, which puts the project's own evaluator of the same language
// (expression.h, checked against muParser by tests/test_expression.cpp) behind the part of
// mu::Parser that drive.cpp calls.
#pragma once

#include <string>
#include <utility>

#include "web/shim/expression.h"

namespace mu {

class ParserError {
 public:
  ParserError(std::string message, int position, std::string token, std::string expression)
      : msg_(std::move(message)),
        pos_(position),
        token_(std::move(token)),
        expr_(std::move(expression)) {}
  const std::string& GetMsg() const { return msg_; }
  int GetPos() const { return pos_; }
  const std::string& GetToken() const { return token_; }
  const std::string& GetExpr() const { return expr_; }

 private:
  std::string msg_;
  int pos_;
  std::string token_;
  std::string expr_;
};

class Parser {
 public:
  using exception_type = ParserError;
  void DefineVar(const std::string& name, double* value) {
    expression_.define_variable(name, value);
  }
  void DefineConst(const std::string& name, double value) {
    expression_.define_constant(name, value);
  }
  // Parses now (muParser waits for the first Eval); drive.cpp calls both in one try block.
  void SetExpr(const std::string& text) {
    try {
      expression_.compile(text);
    } catch (const cb::expression::ExpressionError& e) {
      throw ParserError(e.what(), e.position(), e.token(), text);
    }
  }
  double Eval() const { return expression_.evaluate(); }

 private:
  cb::expression::Expression expression_;
};

}  // namespace mu
