// The rig model shared by every front end: bones with a parent, a rest transform, a length and
// XZX Euler limits, plus the bones whose tips are end effectors.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace ik {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct Bone {
  std::string name;                                                  // for error messages and display; may be empty
  int parent = -1;                                                   // index into Rig::bones, -1 for a root
  Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();                // canonical bone -> rest bone, rigid
  double length = 0;                                                 // tip of the canonical bone is (length, 0, 0)
  Eigen::Vector3d min_deg = Eigen::Vector3d::Constant(-kUnbounded);  // XZX lower limits, degrees
  Eigen::Vector3d max_deg = Eigen::Vector3d::Constant(kUnbounded);   // XZX upper limits, degrees
};

// An optional translation of the whole rig (every root bone moves by it), solved for like the
// angles when `on`: three more unknowns after the 3 * #bones angles, in RIG UNITS (world x, y, z,
// added to the roots' rest translation), within [min, max]. Off (the default), the rig's roots stay
// where their rest transforms put them and nothing else changes.
struct FloatingRoot {
  bool on = false;
  Eigen::Vector3d min = Eigen::Vector3d::Zero();  // rig units, finite, each <= max
  Eigen::Vector3d max = Eigen::Vector3d::Zero();
};

struct Rig {
  std::vector<Bone> bones;
  std::vector<int> effectors;  // bone indices; each bone's tip is an end effector
  FloatingRoot floating_root;
};

// Thrown for any invalid rig or solver input; the message names the bone and the field.
class RigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Checks a rig and throws RigError naming the first problem found:
// parent out of range, a parent cycle, a non-finite number, a rest transform that is not rigid,
// a limit with min > max or with no angle within +-kMaxLimitDeg, a negative length, a length or
// rest translation past kMaxCoordinate, an end effector that is not a bone, a floating root's
// bound that is not finite, past kMaxCoordinate or with min > max, or a rig past the limits of
// size_limits.h. Linear in the number of bones.
void validate_rig(const Rig& rig);

// Checks `effectors` as an end-effector list of `rig` (bone indices, none twice, at least one,
// within the limits of size_limits.h); throws RigError naming the first problem.
void validate_effectors(const Rig& rig, const std::vector<int>& effectors);

// The bones ordered parents before children (roots first). Throws RigError naming a bone on a
// parent cycle. Linear in the number of bones; parents must be in range.
std::vector<int> parents_first(const Rig& rig);

// Joint limits (degrees) must allow an angle within +-this (100 turns); one farther out means none.
constexpr double kMaxLimitDeg = 36000;

// A bone's label for messages: `bone 3 "forearm"`, or `bone 3` when it has no name (or its name
// is "bone 3").
std::string bone_label(const Rig& rig, int index);

}  // namespace ik
