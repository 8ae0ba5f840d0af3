// A signed distance grid as a file (`.nsdf`, written by `needle-sim patient`, docs/PATIENTS.md):
// little-endian, "NSDF", version 1 (u32), the node counts (3 × u32), the origin (3 × f64, m),
// the spacing and the quantum (f64, m), then the values (i16, x fastest, then y, then z). Read back,
// every number is checked as SdfGrid checks it and the size must match the node counts.
#pragma once

#include <stdexcept>
#include <string>

#include "haptics/tissue/sdf_grid.hpp"

namespace needle::haptics::anatomy {

// "FILE: what is wrong".
struct SdfFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string sdf_file_bytes(const SdfGrid& grid);
void write_sdf_file(const std::string& path, const SdfGrid& grid);  // through io::write_file
// Throws SdfFileError: not readable, not an NSDF file, another version, cut short or too long
// for its node counts, or a grid SdfGrid refuses (its reason quoted).
SdfGrid read_sdf_file(const std::string& path);

}  // namespace needle::haptics::anatomy
