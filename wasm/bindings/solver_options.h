// The solver options as JavaScript sees them: camelCase names, every field optional. The names,
// types and defaults come from the core's list (wasm/src/solvers/solver_options.def) through
// for_each_option(), so reading, writing and Solver.defaultOptions() cannot drift from it.
// Only the bindings include this file.
#pragma once

#include <emscripten/val.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "rig.h"
#include "solvers/solver_options.h"

namespace ik::js {

// One option's value from JavaScript, by the field's type; throws RigError naming `where` for a
// value of the wrong type.
inline void read_value(const emscripten::val& v, const std::string& where, bool& out) {
  if (!v.isTrue() && !v.isFalse()) throw RigError(where + " must be true or false");
  out = v.isTrue();
}

inline double read_number(const emscripten::val& v, const std::string& where) {
  if (!v.isNumber()) throw RigError(where + " must be a number");
  return v.as<double>();
}

inline void read_value(const emscripten::val& v, const std::string& where, double& out) { out = read_number(v, where); }

inline void read_value(const emscripten::val& v, const std::string& where, int& out) {
  const double x = read_number(v, where);
  if (!(x == std::floor(x) && std::abs(x) <= 2147483647.0)) throw RigError(where + " must be an integer");
  out = static_cast<int>(x);
}

inline void read_value(const emscripten::val& v, const std::string& where, std::uint32_t& out) {
  const double x = read_number(v, where);
  if (!(x == std::floor(x) && x >= 0 && x <= 4294967295.0)) throw RigError(where + " must be an integer in [0, 2^32)");
  out = static_cast<std::uint32_t>(x);
}

// A field's value as JavaScript receives it (a seed as a plain number).
template <class T>
T js_value(T x) {
  return x;
}
inline double js_value(std::uint32_t x) { return x; }

// Reads a JS options object ({} or undefined: the defaults) whose shape the TypeScript layer has
// checked (web/src/ik/inputs.ts plainOptions: a plain object of known names, numbers and booleans).
// Each option given is read by its field's type, which the conversion to C++ needs: throws
// RigError naming a boolean given for a number, or a fraction for an integer. Ranges are checked by
// Solver::start().
inline SolverOptions read_options(const emscripten::val& js) {
  SolverOptions o;
  if (js.isUndefined() || js.isNull()) return o;
  for_each_option(o, [&](const OptionInfo& info, auto& field) {
    const emscripten::val v = js[info.js_name];
    if (!v.isUndefined()) read_value(v, std::string("solver option ") + info.js_name, field);
  });
  return o;
}

// `message` from Solver::start() with the C++ option name ("option error_tolerance ...") replaced
// by the JavaScript one ("solver option errorTolerance ...").
inline std::string with_js_option_names(const std::string& message) {
  std::string result = message;
  const SolverOptions any;  // only the names are read
  for_each_option(any, [&](const OptionInfo& info, const auto&) {
    const std::string cpp = std::string("option ") + info.name + " ";
    if (message.rfind(cpp, 0) == 0)
      result = std::string("solver option ") + info.js_name + " " + message.substr(cpp.size());
  });
  return result;
}

// The options as a JS object with every field.
inline emscripten::val write_options(const SolverOptions& o) {
  emscripten::val js = emscripten::val::object();
  for_each_option(o, [&](const OptionInfo& info, const auto& field) { js.set(info.js_name, js_value(field)); });
  return js;
}

}  // namespace ik::js
