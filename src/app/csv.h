// Numbers for CSV and JSON: the shortest text that reads back to the same double.
#pragma once

#include <string>

namespace cb {

void append_number(std::string& out, double value);
std::string number_text(double value);
std::string json_string(const std::string& text);  // quoted and escaped

}  // namespace cb
