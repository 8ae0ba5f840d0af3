// The hook `needle-sim bench loop --render-load` uses to keep the GPU and a CPU busy while
// the loop is timed: a function that draws the trainee's frame as fast as it can until `stop`
// turns true. The renderer side provides it by calling set_render_load() from a static
// initialiser in its own cmd_*.cpp; without one, --render-load is a usage error.
#pragma once

#include <atomic>
#include <functional>

namespace needle::cli {

using RenderLoad = std::function<long(const std::atomic<bool>& stop)>;  // returns the frames drawn

void set_render_load(RenderLoad load);
// nullptr when no renderer registered one.
const RenderLoad* render_load();

}  // namespace needle::cli
