#include "haptics/model/urdf_loader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>

#include "io/file_read.hpp"
#include "io/input_limits.hpp"

namespace needle::haptics {
namespace {

// urdfdom reports what it rejects through console_bridge, several lines on stderr per problem,
// and may still return a model (a link whose <inertial> it could not read keeps a zero mass).
// While it parses, its errors are kept instead, for one error line naming the file; its
// warnings and notes are not shown.
class UrdfdomErrors : public console_bridge::OutputHandler {
 public:
  UrdfdomErrors() { console_bridge::useOutputHandler(this); }
  ~UrdfdomErrors() override { console_bridge::restorePreviousOutputHandler(); }
  UrdfdomErrors(const UrdfdomErrors&) = delete;
  UrdfdomErrors& operator=(const UrdfdomErrors&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
    std::string line = text;
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';
    joined += (joined.empty() ? "" : "; ") + line;
  }

  std::string joined;
};

bool finite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

Eigen::Isometry3d to_isometry(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() =
      Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized().toRotationMatrix();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  return t;
}

[[noreturn]] void fail(const std::string& source, const std::string& what) { throw UrdfError(source + ": " + what); }

void check_pose(const urdf::Pose& p, const std::string& source, const std::string& where) {
  if (!finite({p.position.x, p.position.y, p.position.z, p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w}))
    fail(source, where + ": xyz and rpy must be finite numbers");
}

// A link's own mass properties expressed in `frame_of_link` (the frame the link's origin is at).
BodyInertia link_inertia(const urdf::Link& link, const Eigen::Isometry3d& frame_of_link, const std::string& source) {
  BodyInertia b;
  if (!link.inertial) return b;
  const urdf::Inertial& in = *link.inertial;
  const std::string where = "link '" + link.name + "' <inertial>: ";
  if (!finite({in.mass, in.ixx, in.ixy, in.ixz, in.iyy, in.iyz, in.izz}))
    fail(source, where + "mass and inertia must be finite numbers");
  check_pose(in.origin, source, where + "<origin>");
  if (!(in.mass > 0.0)) fail(source, where + "mass must be positive, got " + std::to_string(in.mass));
  Eigen::Matrix3d i;
  i << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(i);
  const Eigen::Vector3d e = eig.eigenvalues();
  if (!(e.minCoeff() > 0.0))
    fail(source,
         where + "inertia tensor must be positive definite (smallest eigenvalue " + std::to_string(e.minCoeff()) + ")");
  // A rigid body's principal moments obey the triangle inequality (each ≤ sum of the other two).
  const double slack = 1e-12 * e.maxCoeff();
  if (e[0] + e[1] < e[2] - slack)
    fail(source, where + "principal moments violate the triangle inequality (no rigid body has them)");
  const Eigen::Isometry3d t = frame_of_link * to_isometry(in.origin);
  b.mass = in.mass;
  b.com = t.translation();
  b.inertia_com = t.linear() * i * t.linear().transpose();
  return b;
}

// Two bodies rigidly joined, both expressed in the same frame (parallel-axis theorem).
BodyInertia combine(const BodyInertia& a, const BodyInertia& b) {
  if (b.mass == 0.0) return a;
  if (a.mass == 0.0) return b;
  BodyInertia c;
  c.mass = a.mass + b.mass;
  c.com = (a.mass * a.com + b.mass * b.com) / c.mass;
  auto shift = [&](const BodyInertia& x) {
    const Eigen::Vector3d d = x.com - c.com;
    return Eigen::Matrix3d(x.inertia_com +
                           x.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
  };
  c.inertia_com = shift(a) + shift(b);
  return c;
}

// (text) => the offset of its first byte that does not begin or continue a whole UTF-8 sequence,
// or -1. TinyXML 2.6 (urdfdom's parser) reads past the end of its buffer on a broken sequence in a
// name (found by tests/fuzz/fuzz_urdf), so such a document never reaches it.
long first_non_utf8_byte(const std::string& text) {
  for (size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const size_t length = lead < 0x80                    ? 1
                          : lead >= 0xC2 && lead <= 0xDF ? 2
                          : lead >= 0xE0 && lead <= 0xEF ? 3
                          : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                         : 0;
    if (length == 0 || i + length > text.size()) return long(i);
    for (size_t k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return long(i);
    i += length;
  }
  return -1;
}

// (text) => the line of the first element nested deeper than io::kMaxNestingDepth, or 0. TinyXML
// (urdfdom's parser) recurses once a level and overflows the stack on a document nested some
// 10,000 deep, so such a document never reaches it. Comments, CDATA, processing instructions and
// declarations nest nothing; a '>' inside an attribute's quotes does not close its tag.
long too_deep_line(const std::string& text) {
  int depth = 0;
  long line = 1;
  auto skip_to = [&](size_t& i, const char* end) {
    const size_t found = text.find(end, i);
    const size_t stop = found == std::string::npos ? text.size() : found + std::strlen(end);
    line += std::count(text.begin() + long(i), text.begin() + long(stop), '\n');
    i = stop;
  };
  for (size_t i = 0; i < text.size();) {
    if (text[i] == '\n') ++line;
    if (text[i] != '<') {
      ++i;
      continue;
    }
    if (text.compare(i, 4, "<!--") == 0)
      skip_to(i, "-->");
    else if (text.compare(i, 9, "<![CDATA[") == 0)
      skip_to(i, "]]>");
    else if (text.compare(i, 2, "<?") == 0)
      skip_to(i, "?>");
    else if (text.compare(i, 2, "<!") == 0)
      skip_to(i, ">");
    else {
      const bool closing = text.compare(i, 2, "</") == 0;
      char quote = 0;
      size_t j = i + 1;
      for (; j < text.size() && (quote || text[j] != '>'); ++j) {
        if (text[j] == '\n') ++line;
        if (quote ? text[j] == quote : text[j] == '"' || text[j] == '\'') quote = quote ? 0 : text[j];
      }
      const bool empty = j < text.size() && text[j - 1] == '/';
      if (closing)
        --depth;
      else if (!empty && ++depth > io::kMaxNestingDepth)
        return line;
      i = j + 1;
    }
  }
  return 0;
}

}  // namespace

RobotModel parse_robot_urdf(const std::string& xml, const std::string& source, std::optional<int> expected_dof) {
  urdf::ModelInterfaceSharedPtr urdf;
  std::string rejected;
  if (const long at = first_non_utf8_byte(xml); at >= 0)
    fail(source, "not a valid URDF document: byte " + std::to_string(at) + " is not UTF-8");
  if (const long line = too_deep_line(xml))
    fail(source, "not a valid URDF document: elements nested deeper than " + std::to_string(io::kMaxNestingDepth) +
                     " levels (line " + std::to_string(line) + ")");
  {
    UrdfdomErrors errors;
    urdf = urdf::parseURDF(xml);
    rejected = errors.joined;
  }
  if (!urdf || !rejected.empty())
    fail(source, "not a valid URDF document: " + (rejected.empty() ? std::string("urdfdom rejected it") : rejected));
  urdf::LinkConstSharedPtr link = urdf->getRoot();
  if (!link) fail(source, "no root link");

  RobotModel model;
  model.name = urdf->getName();
  model.base_link = link->name;
  Eigen::Isometry3d pending = Eigen::Isometry3d::Identity();  // current joint frame (or base) to `link`
  while (!link->child_joints.empty()) {
    if (link->child_joints.size() > 1)
      fail(source, "link '" + link->name + "' has " + std::to_string(link->child_joints.size()) +
                       " child joints; only a serial chain is supported");
    const urdf::Joint& joint = *link->child_joints.front();
    link = urdf->getLink(joint.child_link_name);
    check_pose(joint.parent_to_joint_origin_transform, source, "joint '" + joint.name + "' <origin>");
    const Eigen::Isometry3d to_joint = pending * to_isometry(joint.parent_to_joint_origin_transform);
    switch (joint.type) {
      case urdf::Joint::FIXED:
        pending = to_joint;
        if (!model.joints.empty())
          model.joints.back().body = combine(model.joints.back().body, link_inertia(*link, pending, source));
        break;
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS: {
        JointModel j;
        j.name = joint.name;
        j.origin = to_joint;
        const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
        if (!axis.allFinite() || !(axis.norm() > 1e-9))
          fail(source, "joint '" + joint.name + "': <axis> must be a nonzero vector of finite numbers");
        j.axis = axis.normalized();
        if (joint.dynamics) {
          if (!(joint.dynamics->damping >= 0.0) || !std::isfinite(joint.dynamics->damping))
            fail(source, "joint '" + joint.name + "' <dynamics>: damping must be a finite non-negative number");
          j.damping = joint.dynamics->damping;
        }
        j.body = link_inertia(*link, Eigen::Isometry3d::Identity(), source);
        model.joints.push_back(j);
        pending = Eigen::Isometry3d::Identity();
        break;
      }
      default:
        fail(source, "joint '" + joint.name + "': unsupported type (only revolute, continuous and fixed)");
    }
  }
  model.tip_link = link->name;
  model.tool = pending;

  if (model.joints.empty()) fail(source, "no revolute or continuous joint");
  if (model.dof() > kMaxDof)
    fail(source, std::to_string(model.dof()) + " movable joints, at most " + std::to_string(kMaxDof) + " supported");
  if (expected_dof && model.dof() != *expected_dof)
    fail(source, std::to_string(model.dof()) + " movable joints, expected " + std::to_string(*expected_dof));
  for (const JointModel& j : model.joints)
    if (!(j.body.mass > 0.0)) fail(source, "joint '" + j.name + "' moves no mass (its child link needs an <inertial>)");
  return model;
}

RobotModel load_robot_urdf(const std::string& path, std::optional<int> expected_dof) {
  std::string problem;
  const std::string text = io::read_text(path, problem);
  if (!problem.empty()) throw UrdfError(path + ": " + problem);
  return parse_robot_urdf(text, path, expected_dof);
}

}  // namespace needle::haptics
