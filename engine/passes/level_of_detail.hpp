// Which of a mesh's levels of detail to draw: the finest that still gives each triangle it shows
// a few pixels. llvmpipe sets triangles up on one thread, so a mesh finer than its pixels costs
// frame time without changing what the trainee sees.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/extent.hpp"
#include "engine/model.hpp"
#include "engine/scene.hpp"

namespace needle::engine {

// Below this many covered pixels per front-facing triangle, a coarser level is drawn when the
// asset has one.
constexpr double kMinPixelsPerTriangle = 4.0;

// Radius in pixels of a world-space sphere's outline on a target of this extent, seen by the
// camera; infinite when the camera is inside it.
double projected_radius_px(const Sphere& world, const Camera& camera, Extent extent);

// The finest level (triangle counts, finest first) whose front half, spread over a disc of this
// radius, gives each triangle at least min_pixels; the coarsest when none does.
size_t choose_level(const std::vector<uint32_t>& triangles, double radius_px,
                    double min_pixels = kMinPixelsPerTriangle);

}  // namespace needle::engine
