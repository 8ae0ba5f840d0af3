// Malformed or physically impossible URDFs are errors that name the file and the element.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "haptics/model/urdf_loader.hpp"

namespace needle::haptics {
namespace {

std::string one_joint(const std::string& joint_type, const std::string& inertial, const std::string& extra = "") {
  return R"(<?xml version="1.0"?><robot name="r"><link name="base"/>
    <joint name="j1" type=")" +
         joint_type + R"("><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    <link name="arm">)" +
         inertial + "</link>" + extra + "</robot>";
}

std::string inertial(const std::string& mass, const std::string& ixx, const std::string& iyy, const std::string& izz) {
  return R"(<inertial><mass value=")" + mass + R"("/><inertia ixx=")" + ixx + R"(" ixy="0" ixz="0" iyy=")" + iyy +
         R"(" iyz="0" izz=")" + izz + R"("/></inertial>)";
}

void expect_error(const std::string& xml, const std::string& fragment, std::optional<int> dof = std::nullopt) {
  try {
    parse_robot_urdf(xml, "robot.urdf", dof);
    FAIL() << "expected an error containing '" << fragment << "'";
  } catch (const UrdfError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("robot.urdf: ", 0), 0u) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(ModelUrdf, AcceptsAWellFormedRevoluteJoint) {
  const RobotModel m = parse_robot_urdf(one_joint("revolute", inertial("1", "1", "1", "1")), "robot.urdf", 1);
  EXPECT_EQ(m.dof(), 1);
  EXPECT_EQ(m.joints[0].name, "j1");
  EXPECT_EQ(m.tip_link, "arm");
}

TEST(ModelUrdf, RejectsNegativeMass) {
  expect_error(one_joint("revolute", inertial("-1", "1", "1", "1")), "link 'arm' <inertial>: mass must be positive");
}

TEST(ModelUrdf, RejectsInertiaNotPositiveDefinite) {
  expect_error(one_joint("revolute", inertial("1", "1", "-1", "1")),
               "link 'arm' <inertial>: inertia tensor must be positive definite");
}

TEST(ModelUrdf, RejectsInertiaViolatingTriangleInequality) {
  expect_error(one_joint("revolute", inertial("1", "1", "1", "3")), "triangle inequality");
}

TEST(ModelUrdf, RejectsUnsupportedJointType) {
  expect_error(one_joint("prismatic", inertial("1", "1", "1", "1")), "joint 'j1': unsupported type");
}

TEST(ModelUrdf, RejectsWrongDofCount) {
  expect_error(one_joint("revolute", inertial("1", "1", "1", "1")), "1 movable joints, expected 5", 5);
}

TEST(ModelUrdf, RejectsMasslessMovingBody) { expect_error(one_joint("revolute", ""), "joint 'j1' moves no mass"); }

TEST(ModelUrdf, RejectsBranchingTree) {
  const std::string branch =
      R"(<joint name="j2" type="fixed"><parent link="base"/><child link="other"/></joint><link name="other"/>)";
  expect_error(one_joint("revolute", inertial("1", "1", "1", "1"), branch), "link 'base' has 2 child joints");
}

TEST(ModelUrdf, RejectsMalformedXml) { expect_error("<robot name='r'><link name='a'>", "not a valid URDF document"); }

// urdfdom logs what it cannot read over several lines and may still return a model (a mass of
// "nan" became 0, reported as "must be positive, got 0.000000"): its errors become one line.
TEST(ModelUrdf, WhatUrdfdomRejectsIsOneLineWithItsReason) {
  expect_error(one_joint("revolute", inertial("nan", "1", "1", "1")),
               "robot.urdf: not a valid URDF document: Inertial: mass [nan] is not a float; Could not parse inertial "
               "element for Link [arm]");
  expect_error(one_joint("bogus", inertial("1", "1", "1", "1")),
               "not a valid URDF document: Joint [j1] has no known type [bogus]");
  try {
    parse_robot_urdf(one_joint("revolute", inertial("1", "x", "1", "1")), "robot.urdf");
    FAIL();
  } catch (const UrdfError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

TEST(ModelUrdf, RejectsNumbersThatAreNotFinite) {
  std::string xml = one_joint("revolute", inertial("1", "1", "1", "1"));
  xml.replace(xml.find("<axis"), 0, R"(<origin xyz="0 0 1e999" rpy="0 0 0"/>)");
  expect_error(xml, "not a valid URDF document");  // urdfdom refuses 1e999 itself
  expect_error(one_joint("revolute", inertial("1e999", "1", "1", "1")), "not a valid URDF document");
}

// A broken UTF-8 sequence never reaches urdfdom's TinyXML, which reads past its buffer on one in a
// name (tests/fuzz/regressions/urdf/ holds the input the fuzzer found); whole sequences still parse.
TEST(ModelUrdf, RefusesTextThatIsNotUtf8) {
  std::string xml = one_joint("revolute", inertial("1", "1", "1", "1"));
  const size_t at = xml.find("<robot");
  expect_error(std::string(xml).insert(at, "<!-- \xe6? -->"),
               "not a valid URDF document: byte " + std::to_string(at + 5) + " is not UTF-8");
  expect_error(xml + "\xc3", "not a valid URDF document: byte " + std::to_string(xml.size()) + " is not UTF-8");
  EXPECT_NO_THROW(parse_robot_urdf(std::string(xml).insert(at, "<!-- \u00e9\u2014 -->"), "robot.urdf"));
}

TEST(ModelUrdf, MissingFileIsNamed) {
  try {
    load_robot_urdf("/nonexistent/robot.urdf");
    FAIL();
  } catch (const UrdfError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/robot.urdf: file not found");
  }
}

// `depth` <link> elements nested inside the one-joint robot's arm link.
std::string nested(int depth) {
  std::string links;
  for (int k = 0; k < depth; ++k) links += "<link>";
  for (int k = 0; k < depth; ++k) links += "</link>";
  return one_joint("revolute", inertial("1", "1", "1", "1"), links);
}

TEST(ModelUrdf, ADocumentNestedPastSixtyFourLevelsIsRefusedBeforeTheXmlParserRecursesIntoIt) {
  // 100,000 levels overflowed TinyXML's stack (SIGSEGV); the robot and 63 levels of links in it are within.
  expect_error(nested(100000), "not a valid URDF document: elements nested deeper than 64 levels (line 4)");
  expect_error(nested(63), "No name given for the link");  // reaches urdfdom, which wants its links named
  expect_error(nested(64), "elements nested deeper than 64 levels");
  // Comments, CDATA and a '>' inside quotes nest nothing.
  const std::string quiet = "<!-- <a><b><c> -->" + std::string("<![CDATA[<d><e>]]>");
  EXPECT_EQ(
      parse_robot_urdf(one_joint("revolute", inertial("1", "1", "1", "1") + quiet, "<!-- <x> -->"), "robot.urdf", 1)
          .dof(),
      1);
}

TEST(ModelUrdf, WhatIsNotARegularFileIsRefusedBeforeItIsOpened) {
  const std::string fifo = ::testing::TempDir() + "/robot_fifo_" + std::to_string(::getpid()) + ".urdf";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo, std::string("/dev/zero")}) {  // a pipe nobody writes; endless zeros
    try {
      load_robot_urdf(path);
      ADD_FAILURE() << path;
    } catch (const UrdfError& e) {
      EXPECT_EQ(std::string(e.what()), path + ": not a regular file (a device or a pipe)");
    }
  }
  ::unlink(fifo.c_str());
}

}  // namespace
}  // namespace needle::haptics
