// A generated patient drawn: a mesh of each of its layers (haptics/anatomy/surface_mesh.hpp) in its
// look (patient_look.hpp), placed in the world, added to a task's scene. The skin deforms around the
// needle (the deformation pass's dimple, docs/DEFORMATION.md); the rest stays rigid. The meshes are
// the tissue model's own regions: one geometry for touch and sight.
#pragma once

#include "engine/scene.hpp"
#include "haptics/sim/scenario.hpp"
#include "training/tasks/task.hpp"

namespace needle::app {

// The skin's surface within this distance of the midline is drawn with every triangle of its
// mesh, so that the dent the needle makes moves enough vertices to look round: the band in which
// the epidural's entry counts as in the interspace (training::kInterspaceHalfWidth_m, a design
// value). Elsewhere the dent shows on the simplified mesh's larger triangles; every triangle of
// the band costs the trainee's frame on llvmpipe (docs/BENCHMARKS.md).
inline constexpr double kSkinDetailHalfWidth_m = training::kInterspaceHalfWidth_m;

// The skin's deformation: the layered block's skin's in its task scene (assets/scenes/
// tissue_block_task.json: shear modulus 6 kPa, ν 0.45, ε 6 mm, support 4ε), design values there.
engine::TissueParams patient_skin_deformation();

// (a task's scene, the scenario it runs) => the scene with the scenario's patient's layers added in
// their order, outside in (the section view caps the later ones over the earlier: docs/RENDERING.md);
// the scene as given when the scenario has no patient.
engine::Scene with_patient(engine::Scene scene, const haptics::Scenario& scenario);

// The patient's layer `layer` as a model in the world frame, in its look.
engine::Model patient_layer_model(const haptics::anatomy::Patient& patient, size_t layer,
                                  const Eigen::Vector3d& base_in_world);

}  // namespace needle::app
