// Where the session database lives unless --db says otherwise (run, review, report and sync share
// it), and the station's name unless --station says otherwise.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "training/sessions/session_store.hpp"

namespace needle::app {

// $XDG_DATA_HOME/needle-sim/sessions.db, else ~/.local/share/needle-sim/sessions.db: the
// station's own SQLite file (with PostgreSQL, where a session the server missed is kept).
std::filesystem::path default_db();

// The database to use: --db's value when given, else $NEEDLE_DB, else default_db(). A file or a
// postgresql:// URI.
std::string db_location(const std::optional<std::string>& flag);

// The station's name: --station's value when given, else the host name.
std::string station_name(const std::optional<std::string>& flag);

// A runtime error naming `location` when it is an SQLite file that does not exist: a command that
// reads or corrects a store never makes an empty one.
void require_existing_db(const std::string& location);

// Opens a database that must already exist, read-only (review and report never create, migrate or
// write one); a runtime error naming the file when it does not exist or is damaged.
std::unique_ptr<training::SessionStore> open_existing_db(const std::string& location);

// Where a run keeps what is local to this station (recordings/, runs/, exports/): the folder of an
// SQLite database, the folder of default_db() for a server's.
std::filesystem::path local_folder(const std::string& location);

}  // namespace needle::app
