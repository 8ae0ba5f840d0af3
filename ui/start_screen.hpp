// The start screen (README.md, "Starting a task"): who the trainee is (typed, or one the session
// store knows), the tasks of the assets folder with a line about each and the trainee's last and
// best score, the devices present, and Start. Everything on it answers the keyboard as well as
// the mouse (start_key). Draws into the current ImGui frame.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace needle::ui {

struct StartTask {
  std::string title, description;
  std::string error;                  // the task file does not load: shown, and it cannot start
  std::optional<std::string> record;  // the trainee's past ("last 81, passed  best 85  3 done"); nullopt: never done
};

struct StartDevice {
  std::string spec;   // what a session is run with: mouse, keyboard, gamepad:0, falcon:0
  std::string label;  // "Mouse", "Gamepad 0 (Xbox Controller)", "Falcon"
  std::string help;   // how it moves the needle, or why it cannot be chosen
  bool available = true;
};

struct StartState {
  std::array<char, 64> trainee{};  // the name field
  std::vector<std::string> known_trainees;
  std::vector<StartTask> tasks;
  size_t task = 0;
  std::vector<StartDevice> devices;
  size_t device = 0;
  std::string notice;       // under the buttons: a settings message, why a start failed
  bool focus_name = false;  // put the keyboard in the name field on the next frame
  bool leave_name = false;  // take it out of the name field on the next frame, keeping the name
  bool practice = false;    // start the task as practice: its steps without time limits
};

enum class StartAction { kNone, kStart, kQuit };

// The keys the screen answers besides ImGui's own, by name (the app translates the window's).
enum class StartKey { kUp, kDown, kLeft, kRight, kPageUp, kPageDown, kTab, kEnter, kEscape, kPractice };

StartAction draw_start_screen(StartState& state);

// Up and Down choose the task, Left and Right the device (among those available), Page Up and
// Page Down a trainee the store knows, Tab goes to the name field, P turns practice (untimed steps)
// on and off, Enter starts, Escape quits.
// While the name field has the keyboard (`typing`) Enter still starts, Tab and Escape leave the
// field with the name kept, and the field takes every other key. A start that cannot happen says
// why in the notice instead.
StartAction start_key(StartState& state, StartKey key, bool typing);

// The name in the field without surrounding blanks.
std::string trainee_name(const StartState& state);
void set_trainee_name(StartState& state, const std::string& name);

}  // namespace needle::ui
