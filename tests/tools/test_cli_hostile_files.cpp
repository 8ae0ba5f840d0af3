// Hostile files through needle-sim as a user runs it, each with the exact input that once crashed,
// hung or passed as nonsense: a glTF node chain of 100,000, a URDF nested 100,000 deep, a FIFO and
// /dev/zero given as a robot, a scenario with a million sub-steps or a period of 1e-300, a task
// with a tolerance of 1e300, a checksummed recording holding NaN joints, a mesh without
// primitives. Each is refused with exit 1 and one line naming the file and what is wrong, within
// 10 s: every command runs under `timeout 10`, whose exit code 124 would fail the test as a hang.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "haptics/recording/crc32.hpp"
#include "haptics/recording/session_format.hpp"
#include "tests/support/process_folder.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kAssets = source_dir() / "assets";

ProcessResult within_ten_seconds(const std::string& arguments) {
  return run_command("NEEDLE_VALIDATION=1 timeout 10 " + needle_sim_exe().string() + " " + arguments);
}

size_t line_count(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

// Exit 1, one line, and it holds `text`.
void expect_refused(const ProcessResult& r, const std::string& text) {
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_EQ(line_count(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(text), std::string::npos) << r.output;
}

fs::path folder(const std::string& name) { return process_folder(test_output_dir("cli_hostile_files") / name); }

// The marker asset copied into `dir` (with its buffer) as `name`, its JSON edited.
fs::path edited_marker(const fs::path& dir, const std::string& name, const std::function<void(json&)>& edit) {
  fs::copy_file(kAssets / "marker.bin", dir / "marker.bin", fs::copy_options::overwrite_existing);
  json j = json::parse(std::ifstream(kAssets / "marker.gltf"));
  edit(j);
  std::ofstream(dir / name) << j.dump();
  return dir / name;
}

TEST(CliHostileFiles, AGltfNodeChainOfAHundredThousandIsRefusedAtItsStatedDepth) {
  const fs::path dir = folder("chain");
  const fs::path chain = edited_marker(dir, "chain.gltf", [](json& j) {
    const int mesh = j["nodes"][0]["mesh"];
    j["nodes"] = json::array();
    for (int i = 0; i + 1 < 100000; ++i) j["nodes"].push_back({{"children", {i + 1}}});
    j["nodes"].push_back({{"mesh", mesh}});
    j["scenes"] = {{{"nodes", {0}}}};
    j["scene"] = 0;
  });
  expect_refused(within_ten_seconds("render --gltf " + quoted(chain) + " --out " + quoted(dir / "x.png")),
                 chain.string() + ": nodes[256]: nested deeper than 256 levels of the node hierarchy");
}

TEST(CliHostileFiles, AMeshWithoutPrimitivesIsRefusedAsSuch) {
  const fs::path dir = folder("no_primitives");
  const fs::path file = edited_marker(dir, "empty.gltf", [](json& j) { j["meshes"][0]["primitives"] = json::array(); });
  expect_refused(within_ten_seconds("render --gltf " + quoted(file) + " --out " + quoted(dir / "x.png")),
                 file.string() + ": meshes[0]: has no primitives (glTF requires at least one)");
}

TEST(CliHostileFiles, ADeeplyNestedUrdfIsRefusedBeforeItIsParsed) {
  const fs::path dir = folder("deep_urdf");
  std::string xml = R"(<?xml version="1.0"?><robot name="r"><link name="base"/>)";
  for (int k = 0; k < 100000; ++k) xml += "<link>";
  for (int k = 0; k < 100000; ++k) xml += "</link>";
  std::ofstream(dir / "deep.urdf") << xml << "</robot>\n";
  expect_refused(
      within_ten_seconds("model --robot " + quoted(dir / "deep.urdf") + " --q 0"),
      (dir / "deep.urdf").string() + ": not a valid URDF document: elements nested deeper than 64 levels (line 1)");
}

TEST(CliHostileFiles, AFifoOrADeviceGivenAsARobotIsRefusedWithoutReadingIt) {
  const fs::path fifo = folder("fifo") / "robot.urdf";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& path : {fifo.string(), std::string("/dev/zero")})  // nobody writes the FIFO; zeros never end
    expect_refused(within_ten_seconds("model --robot " + quoted(fs::path(path)) + " --q 0"),
                   path + ": not a regular file (a device or a pipe)");
}

// The thesis's rigid-sphere scenario with `pointer` set to `value`, written into `dir`.
fs::path scenario_with(const fs::path& dir, const std::string& pointer, double value) {
  json s = json::parse(std::ifstream(kAssets / "scenarios/holonomic_sphere.json"));
  for (const char* key : {"master_urdf", "virtual_urdf"})
    s[key] = (kAssets / "robots" / fs::path(s[key].get<std::string>()).filename()).string();
  s[json::json_pointer(pointer)] = value;
  const fs::path file = dir / "scenario.json";
  std::ofstream(file) << s.dump(1);
  return file;
}

TEST(CliHostileFiles, AScenarioThatWouldHangOrFailInsideIsRefusedNamingTheKey) {
  const fs::path dir = folder("scenario");
  fs::path file = scenario_with(dir, "/master_substeps", 1000000);
  expect_refused(within_ten_seconds("simulate --scenario " + quoted(file) + " --out " + quoted(dir / "out")),
                 file.string() + ": /master_substeps: expected a whole number from 1 to 100");
  file = scenario_with(dir, "/period_s", 1e-300);
  expect_refused(within_ten_seconds("simulate --scenario " + quoted(file) + " --out " + quoted(dir / "out")),
                 file.string() + ": /period_s: must be in [0.0001, 0.004] s, got 1e-300");
  file = scenario_with(dir, "/hand/stiffness_N_per_m", 1e300);
  expect_refused(within_ten_seconds("simulate --scenario " + quoted(file) + " --out " + quoted(dir / "out")),
                 file.string() + ": /hand/stiffness_N_per_m: must be in [0, 5000] N/m, got 1e+300");
}

TEST(CliHostileFiles, ATaskWithATolerancePastItsRangeIsRefusedNamingTheKey) {
  const fs::path dir = folder("task");
  json t = json::parse(std::ifstream(kAssets / "tasks/rigid_sphere.json"));
  for (const char* key : {"scene", "scenario"})
    t[key] = fs::weakly_canonical(kAssets / "tasks" / t[key].get<std::string>()).string();
  t["steps"][0]["condition"]["within_m"] = 1e300;
  std::ofstream(dir / "rigid_sphere.json") << t.dump(1);
  expect_refused(
      within_ten_seconds("run --headless --task " + quoted(dir / "rigid_sphere.json") + " --out " +
                         quoted(dir / "out") + " --db " + quoted(dir / "s.db")),
      (dir / "rigid_sphere.json").string() + ": /steps/0/condition/within_m: must be in (0, 1] m, got 1e+300");
}

TEST(CliHostileFiles, ACheckedRecordingWithNaNJointsIsRefusedAsDamagedAtItsTick) {
  const fs::path dir = folder("nan_joints");
  const ProcessResult live = run_needle_sim("run --headless --size 160x120 --trainee ana --task " +
                                            quoted(kAssets / "tasks/rigid_sphere.json") + " --operator sloppy --out " +
                                            quoted(dir / "live") + " --db " + quoted(dir / "s.db"));
  ASSERT_EQ(live.exit_code, 0) << live.output;
  const fs::path recording = json::parse(std::ifstream(dir / "live/score.json"))["recording"].get<std::string>();
  std::ifstream in(recording, std::ios::binary);
  std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // A headless run writes a block a tick. Tick 1000's first joint (the reading's joints follow the
  // tick's 4 x 8 bytes, its sequence, five 32-bit fields and its position), its block's checksums
  // made valid again: only the content is wrong.
  uint32_t header_bytes = 0;
  std::memcpy(&header_bytes, &bytes[12], 4);
  const size_t record_bytes = haptics::session_record_bytes();
  const size_t block = header_bytes + 1000 * (haptics::kBlockHeaderBytes + record_bytes);
  const size_t joint = block + haptics::kBlockHeaderBytes + 32 + 8 + 5 * 4 + 3 * 8;
  const double nan = std::nan("");
  std::memcpy(&bytes[joint], &nan, 8);
  const uint32_t records_crc = haptics::crc32(&bytes[block + haptics::kBlockHeaderBytes], record_bytes);
  std::memcpy(&bytes[block + 16], &records_crc, 4);
  const uint32_t header_crc = haptics::crc32(&bytes[block], 20);
  std::memcpy(&bytes[block + 20], &header_crc, 4);
  const fs::path bad = dir / "nan_joints.nrec";
  std::ofstream(bad, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));

  expect_refused(
      within_ten_seconds("run --headless --size 160x120 --device " + quoted(fs::path("replay:" + bad.string())) +
                         " --out " + quoted(dir / "replay") + " --db " + quoted(dir / "s.db")),
      bad.string() + ": tick 1000 at byte " + std::to_string(block + haptics::kBlockHeaderBytes) +
          ": reading joint_rad[0] = nan, outside [-1e+06, 1e+06]: not what a run records (damaged)");
}

}  // namespace
}  // namespace needle::test
