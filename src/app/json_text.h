// JSON documents are built with nlohmann-json and written by json_text().
//
// Why not nlohmann's dump(): it prints a double as 400.0 or 0.0001 where the CSV and every
// earlier JSON document of this program print 400 and 1e-04 (std::to_chars's shortest
// round-trip form, csv.h). json_text() writes the same compact JSON as dump() but every
// number through csv.h's append_number and every string through json_string, so the one
// number formatter of the program formats the JSON too and the files stay byte-identical.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace cb {

using Json = nlohmann::ordered_json;  // keys stay in the order they were set

std::string json_text(const Json& document);

}  // namespace cb
