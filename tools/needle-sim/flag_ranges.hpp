// Every count and duration a needle-sim flag takes, with its range and why: a number past its
// range is a usage error (exit 2) naming the flag and the range, so no flag makes a run that does
// not end. With the list flags' kMaxListItems they bound each command's whole run. Each command's
// --help shows its flags' ranges (README.md, "The command line").
#pragma once

#include "haptics/realtime/haptic_loop.hpp"
#include "io/input_limits.hpp"
#include "options.hpp"

namespace needle::cli {

// Frames a window shows before it closes itself (run, review): 1e9 is 190 days at 60 fps, a
// window a person closes; the flag is for tests and screenshots.
inline constexpr WholeRange kWindowFrames{1, 1000000000};
// A session's id in the store (SQLite's and PostgreSQL's 64-bit keys, below 2^53 so that a JSON
// reader keeps it exact).
inline constexpr WholeRange kSessionIds{1, 9000000000000000};
// The haptic loop's rate (haptics::check_loop_rate).
inline constexpr NumberRange kLoopRates_hz{haptics::kMinLoopRateHz, haptics::kMaxLoopRateHz};
// A moment or a span of a recording, in seconds from its start: no session lasts longer than
// io::kMaxSessionSeconds.
inline constexpr NumberRange kRecordingTimes_s{0.0, io::kMaxSessionSeconds};

// bench stability --sustained: simulated seconds of sustained contact. 3600 s (the default) take
// about two minutes of wall time; ten times that is the most a bench should ask for (about 20
// minutes). Below 10 s the sustained case says nothing a short case does not. Design values.
inline constexpr NumberRange kSustained_s{10.0, 36000.0};
// bench tick --settle: the scenario played before the ticks are timed; no scenario lasts longer
// than io::kMaxSessionSeconds.
inline constexpr NumberRange kSettle_s{0.0, io::kMaxSessionSeconds, true};
// bench tick --ticks: 1e8 ticks of about 10 us are some 20 minutes.
inline constexpr WholeRange kTimedTicks{1, 100000000};
// bench loop --seconds: measuring time per row; an hour a row is the longest a timing needs.
inline constexpr NumberRange kLoopSeconds{0.0, 3600.0, true};
// bench precision --horizon: simulated seconds per run, above the largest step (4 ms); the
// reference steps at about 1 us, so 10 s (ten million steps) is the most a run should take.
inline constexpr NumberRange kPrecisionHorizon_s{0.004, 10.0, true};
// bench insertion: the tip driven in and out along a line (m, m/s) and held (s); the whole drive,
// in, hold and out, at most io::kMaxSessionSeconds of simulated time (checked together). A needle
// is at most 0.2 m long; a metre is the most any tissue file spans. Design values.
inline constexpr NumberRange kInsertionDepth_m{0.0, 1.0, true};
inline constexpr NumberRange kInsertionSpeed_mps{0.0, 1.0, true};
inline constexpr NumberRange kInsertionHold_s{0.0, io::kMaxSessionSeconds};
// bench insertion --plunger-force: the thumb on the syringe's plunger (N); 100 N is a strong thumb's
// pinch, past the 11 N a loss-of-resistance syringe is pressed with (docs/TISSUE.md). Design value.
inline constexpr NumberRange kPlungerForce_N{0.0, 100.0, true};
// Frames timed per row of the rendering benches (render, deform, ultrasound, frame): 1e5 frames
// of at most ~10 ms on a CPU device are some 20 minutes a row.
inline constexpr WholeRange kBenchFrames{1, 100000};
inline constexpr WholeRange kDeformFrames{2, 100000};       // a pass per frame, the first two differ
inline constexpr WholeRange kUltrasoundFrames{2, 100000};   // the first image warms the pipelines
inline constexpr WholeRange kFrameBenchFrames{10, 100000};  // bench frame: at least a block of 8 and its switch
inline constexpr WholeRange kFrameBenchWarmup{0, 10000};    // bench frame --warmup: frames before the measured ones
// Sphere resolutions of the benches (p = m, (p+1)^2 vertices): 2000 is 4 million vertices; bench
// render's culling and levels of detail are measured up to 4000 (16 million).
inline constexpr WholeRange kDeformSpheres{3, 2000};
inline constexpr WholeRange kRenderSpheres{3, 4000};
// bench store --sessions: sessions each station stores; 16 stations of 10000 are some hours.
inline constexpr WholeRange kStoreSessions{1, 10000};
// bench store --verify: copies verified; 10000 replays of a 48 s session are hours.
inline constexpr WholeRange kVerifySessions{0, 10000};
// verify --jobs: replays at once; more threads than a large machine's cores only share them.
inline constexpr WholeRange kVerifyJobs{1, 256};
// bench frame --variants sweep=N: the ultrasound image made over N frames.
inline constexpr WholeRange kSweepFrames{1, 16};

}  // namespace needle::cli
