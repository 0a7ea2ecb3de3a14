// Bulk copies between JavaScript typed arrays and C++ buffers, and how C++ errors reach
// JavaScript. Only the bindings include this file.
//
// No exception ever crosses into JavaScript: one thrown through WebAssembly frames skips their
// epilogues and destructors, leaking stack (about 32 bytes per error, until the module traps)
// and heap. A binding runs its body in guarded(), which catches every C++ exception, keeps the
// message for take_error() and returns a failure value (null, NaN, false, "" or -1); the
// TypeScript wrappers (web/src/ik/) turn that into a thrown Error. They also hand the bindings
// only typed arrays of the right length and plain option objects, so no JavaScript error can be
// raised inside a binding either.
#pragma once

#include <emscripten/val.h>

#include <exception>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "finite_numbers.h"
#include "rig.h"
#include "size_limits.h"

// wasm/CMakeLists.txt links the module with -sMAXIMUM_MEMORY=IK_WASM_MAXIMUM_MEMORY: the cap the
// core's limits and the messages below are written for (size_limits.h).
static_assert(IK_WASM_MAXIMUM_MEMORY == ik::kMaxWasmMemoryBytes,
              "the link's MAXIMUM_MEMORY (wasm/CMakeLists.txt) and kMaxWasmMemoryBytes (size_limits.h) differ");

namespace ik::js {

// "2 GiB": the most memory the module has (kMaxWasmMemoryBytes).
inline std::string wasm_memory_cap() { return std::to_string(kMaxWasmMemoryBytes >> 30) + " GiB"; }

// The message of the last failed binding call ("" if none since the last take_error()).
inline std::string& last_error() {
  static std::string message;
  return message;
}

// Returns and clears the last error message (JavaScript: module.takeError()).
inline std::string take_error() {
  std::string message;
  message.swap(last_error());
  return message;
}

// Runs `body`; if it throws, keeps the message for take_error() and returns `failure` instead.
template <class Body, class Result = decltype(std::declval<Body>()())>
Result guarded(Body body, Result failure) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    last_error() = "out of memory (the WebAssembly heap is at most " + wasm_memory_cap() + ")";
  } catch (const std::exception& e) {
    last_error() = e.what();
  } catch (...) {
    last_error() = "unknown C++ error";
  }
  return failure;
}

// Length of a JS array-like, or an error naming `what` if it is not one.
inline size_t js_length(const emscripten::val& array, const char* what) {
  const emscripten::val length = array["length"];  // one read: each is a call into JavaScript
  if (!length.isNumber()) throw RigError(std::string(what) + " must be an array or typed array");
  return length.as<size_t>();
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

// Copies a Float64Array the API made, of `n` numbers, into `out` (resized only if needed).
inline void copy_known(const emscripten::val& array, int n, std::vector<double>& out) {
  if (n < 0) throw RigError("a negative array length");
  if (out.size() != static_cast<size_t>(n)) out.resize(n);
  if (n > 0) emscripten::val(emscripten::typed_memory_view(n, out.data())).call<void>("set", array);
}

inline void copy_in(const emscripten::val& array, std::vector<int>& out, const char* what) {
  const size_t n = js_length(array, what);
  out.resize(n);
  emscripten::val view(emscripten::typed_memory_view(n, out.data()));
  view.call<void>("set", array);
}

// Throws RigError naming the first non-finite entry of `values` (the core's check, finite_numbers.h).
inline void check_finite(const double* values, size_t n, const char* what) {
  std::string problem = non_finite_entry(values, n, what);
  if (!problem.empty()) throw RigError(std::move(problem));
}

// A new Float64Array holding a copy of `n` doubles at `data`.
inline emscripten::val copy_out(const double* data, size_t n) {
  // The constructor looked up once (a global lookup by name is a call into JavaScript); kept for
  // the module's life.
  static const emscripten::val* const float64_array = new emscripten::val(emscripten::val::global("Float64Array"));
  return float64_array->new_(emscripten::typed_memory_view(n, data));
}

}  // namespace ik::js
