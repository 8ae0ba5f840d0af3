// Session recordings (haptics::RecordingReader through read_session, and the notes a reader is
// told): any input is a session or a haptics::RecordingError, nothing else, and nothing is
// allocated that the header has not been checked for.
#include "fuzz_input.hpp"
#include "haptics/recording/session_format.hpp"
#include "structure.hpp"

NEEDLE_FUZZ_MUTATIONS(needle::fuzz::extreme_record_value)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string file = needle::fuzz::write_input("fuzz_input.nrec", data, size).string();
  try {
    const needle::haptics::Session session = needle::haptics::read_session(file);
    needle::haptics::recording_notes(file, session.end, session.records.size());
  } catch (const needle::haptics::RecordingError&) {
  }
  return 0;
}
