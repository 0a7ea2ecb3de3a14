#include "a7_rig.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace ik {

namespace {

using nlohmann::json;

double number(const json& v, const std::string& where) {
  if (!v.is_number()) throw RigError(where + " is not a number");
  return v.get<double>();
}

Eigen::Matrix4d read_rest(const json& rows, const std::string& where) {
  if (!rows.is_array() || (rows.size() != 3 && rows.size() != 4))
    throw RigError(where + " must be a 3x4 or 4x4 row-major matrix");
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  for (size_t r = 0; r < rows.size(); ++r) {
    if (!rows[r].is_array() || rows[r].size() != 4)
      throw RigError(where + " row " + std::to_string(r) + " must have 4 numbers");
    for (int c = 0; c < 4; ++c)
      m(r, c) = number(rows[r][c], where + "[" + std::to_string(r) + "][" + std::to_string(c) + "]");
  }
  return m;
}

Eigen::Vector3d read_limit(const json& bone, const char* key, double missing, const std::string& where) {
  if (!bone.contains(key)) return Eigen::Vector3d::Constant(missing);
  const json& v = bone[key];
  if (!v.is_array() || v.size() != 3) throw RigError(where + "." + key + " must be 3 numbers");
  return Eigen::Vector3d(number(v[0], where + "." + key + "[0]"), number(v[1], where + "." + key + "[1]"),
                         number(v[2], where + "." + key + "[2]"));
}

}  // namespace

Rig parse_a7_rig(const std::string& text, const std::string& file) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw RigError(file + ": bad JSON: " + e.what());
  }
  if (!doc.is_object() || !doc.contains("bones") || !doc["bones"].is_array())
    throw RigError(file + ": no \"bones\" array");
  Rig rig;
  try {
    const json& bones = doc["bones"];
    for (size_t i = 0; i < bones.size(); ++i) {
      const std::string where = "bones[" + std::to_string(i) + "]";
      const json& b = bones[i];
      if (!b.is_object()) throw RigError(where + " is not an object");
      Bone bone;
      if (b.contains("name") && b["name"].is_string()) bone.name = b["name"].get<std::string>();
      if (!b.contains("parent_id")) throw RigError(where + ".parent_id is missing");
      bone.parent = static_cast<int>(number(b["parent_id"], where + ".parent_id"));
      bone.length = b.contains("length") ? number(b["length"], where + ".length") : 0.0;
      if (!b.contains("rest_T")) throw RigError(where + ".rest_T is missing");
      bone.rest = read_rest(b["rest_T"], where + ".rest_T");
      bone.min_deg = read_limit(b, "xzx_min", -kUnbounded, where);
      bone.max_deg = read_limit(b, "xzx_max", kUnbounded, where);
      rig.bones.push_back(bone);
    }
    if (doc.contains("ik_constraints")) {
      const json& c = doc["ik_constraints"];
      if (c.is_number()) {
        rig.effectors.push_back(static_cast<int>(c.get<double>()));
      } else if (c.is_array()) {
        for (size_t k = 0; k < c.size(); ++k)
          rig.effectors.push_back(static_cast<int>(number(c[k], "ik_constraints[" + std::to_string(k) + "]")));
      } else {
        throw RigError("ik_constraints must be a bone index or a list of them");
      }
    } else if (!rig.bones.empty()) {
      rig.effectors.push_back(static_cast<int>(rig.bones.size()) - 1);
    }
    validate_rig(rig);
  } catch (const RigError& e) {
    throw RigError(file + ": " + e.what());
  }
  return rig;
}

Rig load_a7_rig(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw RigError(path + ": cannot open file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_a7_rig(buffer.str(), path);
}

}  // namespace ik
