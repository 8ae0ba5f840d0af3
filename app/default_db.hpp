// Where the session database lives unless --db says otherwise: run, review and report share it.
#pragma once

#include <filesystem>
#include <memory>

#include "training/sessions/session_store.hpp"

namespace needle::app {

// $XDG_DATA_HOME/needle-sim/sessions.db, else ~/.local/share/needle-sim/sessions.db.
std::filesystem::path default_db();

// Opens a database that must already exist, read-only (review and report never create, migrate or
// write one); a runtime error naming the file when it does not exist or is damaged.
std::unique_ptr<training::SessionStore> open_existing_db(const std::filesystem::path& file);

}  // namespace needle::app
