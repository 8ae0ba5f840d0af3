// The committed assets (assets/*.gltf), built in memory. Frame: metres, z up (the thesis's
// robot base frame), so they are placed in scenes without a Y-up to Z-up turn.
#pragma once

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace needle::asset_gen {

constexpr double kThesisSphereRadius = 0.1;   // m, thesis section 4.2
constexpr double kThesisSphereCenterX = 0.4;  // m, centre (0.4, 0, 0)

// Thesis sphere (shapes.hpp, sphere_mesh) of radius 0.1 m, its node at (0.4, 0, 0);
// buffer file "sphere_P.bin" (or "sphere_PxM.bin" when P != M). With lod_steps, coarser levels
// of detail over every step-th parallel and meridian (sphere_indices), finest first.
tinygltf::Model make_sphere(int parallels, int meridians, const std::vector<int>& lod_steps = {});

// Needle along the x axis: tip (a short cone) at the node origin pointing +x like the thesis's
// x5 axis, shaft and coloured hub along -x.
tinygltf::Model make_needle();

// Tissue block 0.1 x 0.1 m, top (skin) at z = 0: skin (textured), fat, muscle, bone plate.
tinygltf::Model make_tissue_block();

// Midline section of the lower back for the epidural task, 0.1 x 0.1 m, skin at z = 0, the spine
// along x: skin 3 mm, subcutaneous fat 12 mm, supraspinous ligament 6 mm, the interspinous
// ligament 22 mm in a 12 mm window between the laminae above (x < 0) and below, ligamentum flavum
// 5 mm, epidural space 5 mm, dura 0.5 mm, cerebrospinal fluid 15 mm, vertebral body 30 mm; one
// mesh and material per part (the layers of assets/scenarios/epidural.json).
tinygltf::Model make_lumbar_section();

// Guidance marker: a 3 mm sphere at the origin.
tinygltf::Model make_marker();

struct GeneratedAsset {
  std::string file;  // e.g. "sphere_100.gltf"; its .bin (and .png) sit next to it
  tinygltf::Model model;
};

// Every asset committed under assets/.
std::vector<GeneratedAsset> committed_assets();

// Writes `asset` (glTF + external buffer and images) into `folder`; throws on failure.
void write_asset(const GeneratedAsset& asset, const std::filesystem::path& folder);

}  // namespace needle::asset_gen
