// A generated lumbar patient: the spine of spine.hpp sampled on one lattice and cut into the
// tissue layers of the needle's path (docs/PATIENTS.md), each a signed distance grid, placed so that
// the skin over the L3–L4 interspace, on the midline, lies where the caller says. The same fields
// feed the tissue model, the rendered meshes, the section view and the ultrasound image.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "haptics/anatomy/lattice_field.hpp"
#include "haptics/anatomy/patient_params.hpp"
#include "haptics/anatomy/spine.hpp"
#include "haptics/anatomy/surface_mesh.hpp"
#include "haptics/tissue/tissue_model.hpp"

namespace needle::haptics::anatomy {

// One layer of the patient, outside in: its name, its region and the tissue parameter set
// (assets/tissues/<parameters>.json) it is made of.
struct PatientLayer {
  std::string name;
  LayerShape shape;
  std::string parameters;
  bool rigid = false;
};

// The midline approach to an interspace, in the model's frame: where the needle meets the skin
// (between the spinous processes' tips) and the centre of the interlaminar window it aims at.
struct Approach {
  Eigen::Vector3d entry;
  Eigen::Vector3d window;
  Eigen::Vector3d direction() const { return (window - entry).normalized(); }
};

struct Patient {
  PatientParams params;
  Spine spine;                   // the patient's frame
  Eigen::Vector3d origin;        // where the patient frame's origin lies in the model's frame
  double fat_thickness_m = 0.0;  // subcutaneous, over the deep tissue
  std::vector<PatientLayer> layers;
  std::array<Approach, 5> approaches;         // "L1-L2" ... "L5-S1", model frame
  std::array<Eigen::Vector3d, 2> crest_tops;  // the iliac crests' highest points, model frame (Tuffier's line)
  size_t field_bytes = 0;                     // the grids' memory, each shared grid once

  Eigen::Vector3d to_model(const Eigen::Vector3d& patient_point) const { return patient_point + origin; }
};

// The layers, outside in (tasks name them), each with the tissue parameter set it is made of
// (assets/tissues/<parameters>.json) and whether it is bone.
struct PatientLayerSpec {
  const char* name;
  const char* parameters;
  bool rigid;
};
inline constexpr std::array<PatientLayerSpec, 12> kPatientLayers{{{"skin", "skin", false},
                                                                  {"subcutaneous fat", "subcutaneous_fat", false},
                                                                  {"erector spinae", "muscle", false},
                                                                  {"supraspinous ligament", "spinal_ligament", false},
                                                                  {"interspinous ligament", "spinal_ligament", false},
                                                                  {"ligamentum flavum", "ligamentum_flavum", false},
                                                                  {"epidural space", "epidural_space", false},
                                                                  {"dura", "dura", false},
                                                                  {"cerebrospinal fluid", "cerebrospinal_fluid", false},
                                                                  {"intervertebral disc", "spinal_ligament", false},
                                                                  {"bone", "bone", true},
                                                                  {"iliac crest", "bone", true}}};

// Design value: a 1 mm lattice resolves the 4 mm flavum and the 5 mm posterior epidural space on the
// needle's path with its sampling error a few hundredths of a millimetre on their faces (docs/PATIENTS.md),
// and keeps a patient's fields near 20 MB; a 4 µm quantum spans ±131 mm in 16 bits.
inline const Lattice kPatientLattice{1e-3, 4e-6, Eigen::Vector3d::Zero()};

// (patient parameters, where the skin over L3–L4 on the midline goes in the model's frame) => the
// patient. Deterministic: the same parameters give the same fields, bit for bit.
Patient generate_patient(const PatientParams& params, const Eigen::Vector3d& l3_l4_entry = Eigen::Vector3d::Zero(),
                         const Lattice& lattice = kPatientLattice);

// A layer's mesh (surface_mesh.hpp) every `stride` nodes, inset 0.5 mm inside the grid's box for each
// earlier layer made of the same grid (design value: half a millimetre keeps the nested walls apart
// for the depth test and the section's caps, a tenth of the grid's spacing).
SurfaceMesh layer_surface(const Patient& patient, size_t layer, int stride);

// The patient's layers as a tissue model with no mechanics but the bones' rigidity: what the
// geometry alone says (where the needle meets which layer), for reports and tests.
TissueModel geometry_model(const Patient& patient);

}  // namespace needle::haptics::anatomy
