// Progress of long work on stderr: a line rewritten in place on a terminal, a plain line
// every few seconds otherwise, nothing with --quiet.
#pragma once

#include <chrono>
#include <string>

namespace cb {

class Progress {
 public:
  // `unit` names what is counted ("frames"): then the line shows the count and the rate.
  Progress(std::string what, double total, bool quiet, std::string unit = "");
  ~Progress();
  void update(double done);  // cheap: prints at most a few times a second

 private:
  std::string what_, unit_;
  double total_;
  bool quiet_, tty_;
  bool printed_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace cb
