// How needle-sim's help reads: each command's usage line made from its options (required ones
// bare, the others in brackets, two that exclude each other as alternatives), an option's value
// shown by its form alone ("--ticks N"), and the commands listed by their full names.
#pragma once

#include <CLI/App.hpp>
#include <memory>
#include <string>

namespace needle::cli {

// The formatter for the root app; its commands take it on when they are added.
std::shared_ptr<CLI::Formatter> help_formatter();

// "needle-sim bench tick": the app's words from the root.
std::string full_name(const CLI::App* app);

}  // namespace needle::cli
