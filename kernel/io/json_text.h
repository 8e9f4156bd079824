// json_text.h -- JSON text to a document, with positioned syntax errors, for the readers.
//
// Computes: the nlohmann::json document of `text`, as nlohmann's own DOM parser builds it,
// except that
//  - every syntax error (and a number that overflows to infinity) is reported as
//    JsonSyntaxError "<source>:<line>:<column>: invalid JSON: <reason>", 1-based positions;
//  - with numbers_as_text, every number token that is not a 64-bit integer (a fraction, an
//    exponent, or an integer beyond 64 bits) is kept as the string of its own text, so the
//    caller reads it exactly (nlohmann would round it to a double); integers stay integers;
//  - with reject_duplicate_keys, a key repeated in one object is a JsonSyntaxError naming
//    the key (nlohmann keeps the last value silently).
// Readers catch JsonSyntaxError and rethrow their own error type (shape_json, complex_json).
// Complexity: O(text size).
#pragma once

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

#include "support/format_error.h"

namespace grassfire {

class JsonSyntaxError : public FormatError {  // support/format_error.h: the contract of what()
 public:
  using FormatError::FormatError;
};

struct JsonReadOptions {
  bool numbers_as_text = false;
  bool reject_duplicate_keys = false;
};

nlohmann::json parse_json_text(const std::string& text, const std::string& source, const JsonReadOptions& options = {});

}  // namespace grassfire
