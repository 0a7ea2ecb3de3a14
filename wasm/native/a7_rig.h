// Reads an A7 course rig (JSON, format in PROTOCOL.md) into the rig model. Native builds only:
// the web front ends parse rigs in TypeScript (web/src/rig/a7/a7_rig.ts) and pass arrays through the
// bindings; tests/bench/protocol_agreement.test.ts reads every test rig both ways.
#pragma once

#include <string>

#include "../src/rig.h"

namespace ik {

// Parses A7 JSON text. `file` names the source in error messages. Limits missing from the file
// are unbounded; a rig without `ik_constraints` takes its last bone as the end effector.
// Throws RigError naming the file, the bone and the field on malformed input.
Rig parse_a7_rig(const std::string& json_text, const std::string& file);

// Reads and parses an A7 JSON file.
Rig load_a7_rig(const std::string& path);

}  // namespace ik
