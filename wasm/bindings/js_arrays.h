// Bulk copies between JavaScript typed arrays and C++ buffers, and C++ errors as JS exceptions.
// Only the bindings include this file.
#pragma once

#include <emscripten/val.h>

#include <exception>
#include <string>
#include <vector>

#include "rig.h"

namespace ik::js {

// Throws a JavaScript Error carrying `message`. The message is copied into a JS string first,
// so no C++ object is left behind when the exception unwinds into JavaScript.
[[noreturn]] inline void throw_error(const std::string& message) {
  emscripten::val error = emscripten::val::global("Error").new_(emscripten::val(message));
  error.throw_();
}

// Runs `body` and turns any C++ exception into a JavaScript Error with the same message.
template <class Body>
auto guarded(Body body) -> decltype(body()) {
  std::string message;
  try {
    return body();
  } catch (const std::exception& e) {
    message = e.what();
  }
  throw_error(message);
}

// Length of a JS array-like, or an error naming `what` if it is not one.
inline size_t js_length(const emscripten::val& array, const char* what) {
  if (!array.hasOwnProperty("length") && array["length"].isUndefined())
    throw RigError(std::string(what) + " must be an array or typed array");
  return array["length"].as<size_t>();
}

// Copies a JS array of `expected` numbers into `out` (resized only if needed) in one bulk set.
inline void copy_in(const emscripten::val& array, size_t expected, std::vector<double>& out, const char* what) {
  const size_t n = js_length(array, what);
  if (n != expected)
    throw RigError(std::string(what) + " has " + std::to_string(n) + " values, expected " + std::to_string(expected));
  if (out.size() != n) out.resize(n);
  emscripten::val view(emscripten::typed_memory_view(n, out.data()));
  view.call<void>("set", array);
}

inline void copy_in(const emscripten::val& array, std::vector<int>& out, const char* what) {
  const size_t n = js_length(array, what);
  out.resize(n);
  emscripten::val view(emscripten::typed_memory_view(n, out.data()));
  view.call<void>("set", array);
}

// Throws RigError naming the first non-finite entry of `values`.
inline void check_finite(const double* values, size_t n, const char* what) {
  for (size_t i = 0; i < n; ++i)
    if (!(values[i] - values[i] == 0))
      throw RigError(std::string(what) + "[" + std::to_string(i) + "] is not a finite number");
}

// A new Float64Array holding a copy of `n` doubles at `data`.
inline emscripten::val copy_out(const double* data, size_t n) {
  return emscripten::val::global("Float64Array").new_(emscripten::typed_memory_view(n, data));
}

}  // namespace ik::js
