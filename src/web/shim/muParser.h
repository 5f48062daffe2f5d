// Stands in for muParser in the page's build: Debian ships muParser as a compiled x86-64
// library only, and the page may not carry a copy of its sources. drive.cpp compiles unchanged
// against this header; an "expr" drive then fails when it is made, with a message the page
// shows next to the scene (every other drive is the program's code, bit for bit).
#pragma once

#include <string>

namespace mu {

class ParserError {
 public:
  const std::string& GetMsg() const { return msg_; }

 private:
  std::string msg_ =
      "expression drives need the command-line program (muParser has no WebAssembly build); "
      "in the page use a ramp, step, sine, impulses or table drive";
};

class Parser {
 public:
  using exception_type = ParserError;
  void DefineVar(const std::string&, double*) {}
  void DefineConst(const std::string&, double) {}
  void SetExpr(const std::string&) { throw ParserError(); }
  double Eval() const { throw ParserError(); }
};

}  // namespace mu
