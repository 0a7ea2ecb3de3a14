// The solver options as JavaScript sees them: camelCase names, every field optional. One table
// maps each name to its SolverOptions field, so reading and writing cannot drift apart.
// Only the bindings include this file.
#pragma once

#include <emscripten/val.h>

#include <cmath>
#include <string>

#include "rig.h"
#include "solvers/solver.h"

namespace ik::js {

enum class OptionKind { number, integer, boolean, seed };

struct OptionField {
  const char* name;     // camelCase, as JavaScript passes it
  const char* cpp_name; // the SolverOptions field, as C++ messages name it
  OptionKind kind;
  double SolverOptions::*number = nullptr;
  int SolverOptions::*integer = nullptr;
  bool SolverOptions::*boolean = nullptr;
};

inline const OptionField kOptionFields[] = {
    {"gradientTolerance", "gradient_tolerance", OptionKind::number, &SolverOptions::gradient_tolerance},
    {"errorTolerance", "error_tolerance", OptionKind::number, &SolverOptions::error_tolerance},
    {"maxIterations", "max_iterations", OptionKind::integer, nullptr, &SolverOptions::max_iterations},
    {"timeBudgetSeconds", "time_budget_s", OptionKind::number, &SolverOptions::time_budget_s},
    {"tipTolerance", "tip_tolerance", OptionKind::number, &SolverOptions::tip_tolerance},
    {"historyCapacity", "history_capacity", OptionKind::integer, nullptr, &SolverOptions::history_capacity},
    {"paperMode", "paper_mode", OptionKind::boolean, nullptr, nullptr, &SolverOptions::paper_mode},
    {"fdStepDeg", "fd_step_deg", OptionKind::number, &SolverOptions::fd_step_deg},
    {"gdInitialStep", "gd_initial_step", OptionKind::number, &SolverOptions::gd_initial_step},
    {"backtrackFactor", "backtrack_factor", OptionKind::number, &SolverOptions::backtrack_factor},
    {"armijoC1", "armijo_c1", OptionKind::number, &SolverOptions::armijo_c1},
    {"maxBacktracks", "max_backtracks", OptionKind::integer, nullptr, &SolverOptions::max_backtracks},
    {"gnSingularCutoff", "gn_singular_cutoff", OptionKind::number, &SolverOptions::gn_singular_cutoff},
    {"gnMaxStepDeg", "gn_max_step_deg", OptionKind::number, &SolverOptions::gn_max_step_deg},
    {"newtonMaxStepDeg", "newton_max_step_deg", OptionKind::number, &SolverOptions::newton_max_step_deg},
    {"lmInitialMu", "lm_initial_mu", OptionKind::number, &SolverOptions::lm_initial_mu},
    {"lmDampingFloor", "lm_damping_floor", OptionKind::number, &SolverOptions::lm_damping_floor},
    {"lmMaxRejections", "lm_max_rejections", OptionKind::integer, nullptr, &SolverOptions::lm_max_rejections},
    {"restarts", "restarts", OptionKind::integer, nullptr, &SolverOptions::restarts},
    {"stallIterations", "stall_iterations", OptionKind::integer, nullptr, &SolverOptions::stall_iterations},
    {"seed", "seed", OptionKind::seed},
    {"escapeSaddles", "escape_saddles", OptionKind::boolean, nullptr, nullptr, &SolverOptions::escape_saddles},
    {"chainRestarts", "chain_restarts", OptionKind::integer, nullptr, &SolverOptions::chain_restarts},
};

// Reads a JS options object ({} or undefined: the defaults). Throws RigError naming an unknown
// field or a value of the wrong type; ranges are checked by Solver::start().
inline SolverOptions read_options(const emscripten::val& js) {
  SolverOptions o;
  if (js.isUndefined() || js.isNull()) return o;
  if (js.typeOf().as<std::string>() != "object") throw RigError("solver options must be an object");
  const emscripten::val keys = emscripten::val::global("Object").call<emscripten::val>("keys", js);
  const size_t count = keys["length"].as<size_t>();
  for (size_t k = 0; k < count; ++k) {
    const std::string key = keys[k].as<std::string>();
    const OptionField* field = nullptr;
    for (const OptionField& f : kOptionFields)
      if (key == f.name) field = &f;
    if (!field) {
      std::string known;
      for (const OptionField& f : kOptionFields) known += (known.empty() ? "" : ", ") + std::string(f.name);
      throw RigError("unknown solver option \"" + key + "\" (known: " + known + ")");
    }
    const emscripten::val v = js[key];
    if (v.isUndefined()) continue;
    const std::string where = "solver option " + key;
    if (field->kind == OptionKind::boolean) {
      if (!v.isTrue() && !v.isFalse()) throw RigError(where + " must be true or false");
      o.*(field->boolean) = v.isTrue();
      continue;
    }
    if (!v.isNumber()) throw RigError(where + " must be a number");
    const double x = v.as<double>();
    switch (field->kind) {
      case OptionKind::number:
        o.*(field->number) = x;
        break;
      case OptionKind::integer:
        if (!(x == std::floor(x) && std::abs(x) <= 2147483647.0)) throw RigError(where + " must be an integer");
        o.*(field->integer) = static_cast<int>(x);
        break;
      case OptionKind::seed:
        if (!(x == std::floor(x) && x >= 0 && x <= 4294967295.0))
          throw RigError(where + " must be an integer in [0, 2^32)");
        o.seed = static_cast<std::uint32_t>(x);
        break;
      case OptionKind::boolean:
        break;
    }
  }
  return o;
}

// `message` from Solver::start() with the C++ option name ("option error_tolerance ...") replaced
// by the JavaScript one ("solver option errorTolerance ...").
inline std::string with_js_option_names(const std::string& message) {
  for (const OptionField& f : kOptionFields) {
    const std::string cpp = std::string("option ") + f.cpp_name + " ";
    if (message.rfind(cpp, 0) == 0) return std::string("solver option ") + f.name + " " + message.substr(cpp.size());
  }
  return message;
}

// The options as a JS object with every field.
inline emscripten::val write_options(const SolverOptions& o) {
  emscripten::val js = emscripten::val::object();
  for (const OptionField& f : kOptionFields) {
    switch (f.kind) {
      case OptionKind::number: js.set(f.name, o.*(f.number)); break;
      case OptionKind::integer: js.set(f.name, o.*(f.integer)); break;
      case OptionKind::boolean: js.set(f.name, o.*(f.boolean)); break;
      case OptionKind::seed: js.set(f.name, static_cast<double>(o.seed)); break;
    }
  }
  return js;
}

}  // namespace ik::js
