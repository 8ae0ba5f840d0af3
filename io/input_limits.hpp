// Limits on what an input file may ask of a run, shared by the readers of every format: a
// scenario's length and its operator's waypoint times, a recording's length, the run that plays
// them. A number past a limit is an error naming the file, never a run that does not end.
#pragma once

namespace needle::io {

// The longest session a run, a scenario or a recording may describe: 30 minutes. A guided task
// lasts minutes; past this a file is taken to be wrong (a waypoint at t = 1e308, a recording
// that grows without end), not a session.
inline constexpr double kMaxSessionSeconds = 1800.0;

}  // namespace needle::io
