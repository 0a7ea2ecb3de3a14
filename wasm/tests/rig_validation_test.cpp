#include <gtest/gtest.h>

#include "a7_fixtures.h"
#include "small_rigs.h"

namespace ik {
namespace {

using test::two_bones;

void expect_error(const Rig& rig, const std::string& fragment) {
  try {
    Kinematics kin(rig);
    FAIL() << "expected an error containing: " << fragment;
  } catch (const RigError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(RigValidation, AcceptsAValidRig) { EXPECT_NO_THROW(Kinematics kin(two_bones())); }

TEST(RigValidation, ParentOutOfRange) {
  Rig rig = two_bones();
  rig.bones[1].parent = 7;
  expect_error(rig, "bone 1 \"lower\": parent 7 is out of range");
}

TEST(RigValidation, ParentCycle) {
  Rig rig = two_bones();
  rig.bones[0].parent = 1;
  expect_error(rig, "parent chain has a cycle");
}

TEST(RigValidation, NonFiniteNumbers) {
  Rig rig = two_bones();
  rig.bones[1].rest(1, 3) = std::nan("");
  expect_error(rig, "bone 1 \"lower\": rest_T has a non-finite entry");
  rig = two_bones();
  rig.bones[0].length = INFINITY;
  expect_error(rig, "bone 0 \"upper\": length is not finite");
  rig = two_bones();
  rig.bones[0].min_deg[2] = std::nan("");
  expect_error(rig, "xzx_min/xzx_max[2] is NaN");
}

TEST(RigValidation, NonRigidRest) {
  Rig rig = two_bones();
  rig.bones[1].rest(0, 0) = 2;  // a scale
  expect_error(rig, "bone 1 \"lower\": rest_T is not rigid");
  rig = two_bones();
  rig.bones[1].rest(2, 2) = -1;  // a mirror
  expect_error(rig, "mirrors");
  rig = two_bones();
  rig.bones[1].rest(3, 0) = 0.5;
  expect_error(rig, "bottom row");
}

TEST(RigValidation, MinAboveMax) {
  Rig rig = two_bones();
  rig.bones[1].min_deg[1] = 30;
  rig.bones[1].max_deg[1] = 10;
  expect_error(rig, "bone 1 \"lower\": limit xzx_min/xzx_max[1] has min 30 > max 10");
}

TEST(RigValidation, EffectorNotABone) {
  Rig rig = two_bones();
  rig.effectors = {1, 5};
  expect_error(rig, "end effector 1 is bone 5, which is not a bone");
  rig.effectors = {};
  expect_error(rig, "no end effectors");
}

TEST(RigValidation, SetEffectorsKeepsTheOldListOnError) {
  Kinematics kin(two_bones());
  EXPECT_THROW(kin.set_effectors({0, 9}), RigError);
  EXPECT_EQ(kin.rig().effectors, std::vector<int>{1});
  kin.set_effectors({0, 1});
  EXPECT_EQ(kin.num_effectors(), 2);
}

using A7ReportRigs = test::NeedsA7;

TEST_F(A7ReportRigs, ReadsTheFiveRigs) {
  const int bones[] = {5, 7, 19, 21, 22};
  const int effectors[] = {1, 1, 5, 5, 5};
  for (size_t i = 0; i < test::a7_rig_names().size(); ++i) {
    const Rig rig = test::load_a7(test::a7_rig_names()[i]);
    EXPECT_EQ(static_cast<int>(rig.bones.size()), bones[i]);
    EXPECT_EQ(static_cast<int>(rig.effectors.size()), effectors[i]);
  }
  EXPECT_EQ(test::load_a7("robot-arm").effectors, std::vector<int>{6});  // no ik_constraints: last bone
}

TEST(A7Reader, TakesTheLastBoneAsEffectorWithoutIkConstraints) {
  const Rig rig = parse_a7_rig(R"({"bones":[{"parent_id":-1,"rest_T":[[1,0,0,0],[0,1,0,0],[0,0,1,0]]},)"
                               R"({"parent_id":0,"rest_T":[[1,0,0,0],[0,1,0,0],[0,0,1,0]]}]})",
                               "rig.json");
  EXPECT_EQ(rig.effectors, std::vector<int>{1});
}

TEST(A7Reader, ErrorsNameTheFileAndField) {
  auto message = [](const std::string& text) {
    try {
      parse_a7_rig(text, "rig.json");
    } catch (const RigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("{ not json").find("rig.json: bad JSON"), std::string::npos);
  EXPECT_NE(message("{}").find("rig.json: no \"bones\" array"), std::string::npos);
  EXPECT_NE(message(R"({"bones":[{"parent_id":-1,"rest_T":[[1,0,0],[0,1,0,0],[0,0,1,0]]}]})")
                .find("rig.json: bones[0].rest_T row 0"),
            std::string::npos);
  EXPECT_NE(message(R"({"bones":[{"parent_id":-1,"length":"x","rest_T":[[1,0,0,0],[0,1,0,0],[0,0,1,0]]}]})")
                .find("bones[0].length is not a number"),
            std::string::npos);
  EXPECT_NE(message(R"({"ik_constraints":3,"bones":[{"parent_id":-1,"rest_T":[[1,0,0,0],[0,1,0,0],[0,0,1,0]]}]})")
                .find("end effector 0 is bone 3"),
            std::string::npos);
}

}  // namespace
}  // namespace ik
