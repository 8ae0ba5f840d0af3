#include "ui/start_screen.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstring>

namespace needle::ui {
namespace {

const ImVec4 kGood(0.35f, 0.8f, 0.4f, 1.0f), kBad(0.9f, 0.3f, 0.25f, 1.0f), kDim(0.6f, 0.6f, 0.6f, 1.0f);

// Why Start cannot happen now; empty when it can.
std::string cannot_start(const StartState& s) {
  if (trainee_name(s).empty()) return "Type your name first (Tab goes to the name field).";
  if (s.tasks.empty()) return "No task found in the assets folder.";
  if (!s.tasks[s.task].error.empty()) return "This task's file does not load: choose another.";
  if (s.devices.empty() || !s.devices[s.device].available) return "This device is not available: choose another.";
  return "";
}

StartAction try_start(StartState& s) {
  const std::string why = cannot_start(s);
  if (why.empty()) return StartAction::kStart;
  s.notice = why;
  return StartAction::kNone;
}

void step_device(StartState& s, int by) {
  const size_t n = s.devices.size();
  for (size_t tried = 1; tried < n; ++tried) {
    const size_t next = (s.device + (by > 0 ? tried : n - tried)) % n;
    if (s.devices[next].available) {
      s.device = next;
      return;
    }
  }
}

void section(const char* title, const char* keys) {
  ImGui::Spacing();
  ImGui::TextUnformatted(title);
  ImGui::SameLine();
  ImGui::TextColored(kDim, "%s", keys);
}

}  // namespace

std::string trainee_name(const StartState& s) {
  const std::string raw(s.trainee.data(), strnlen(s.trainee.data(), s.trainee.size()));
  const size_t first = raw.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return raw.substr(first, raw.find_last_not_of(" \t") - first + 1);
}

void set_trainee_name(StartState& s, const std::string& name) {
  s.trainee.fill('\0');
  std::memcpy(s.trainee.data(), name.data(), std::min(name.size(), s.trainee.size() - 1));
}

StartAction start_key(StartState& s, StartKey key, bool typing) {
  if (typing) {
    if (key == StartKey::kEnter) return try_start(s);
    if (key == StartKey::kTab || key == StartKey::kEscape) s.leave_name = true;
    return StartAction::kNone;
  }
  const size_t tasks = s.tasks.size();
  switch (key) {
    case StartKey::kUp:
      if (tasks) s.task = (s.task + tasks - 1) % tasks;
      break;
    case StartKey::kDown:
      if (tasks) s.task = (s.task + 1) % tasks;
      break;
    case StartKey::kLeft:
      step_device(s, -1);
      break;
    case StartKey::kRight:
      step_device(s, 1);
      break;
    case StartKey::kPageUp:
    case StartKey::kPageDown: {
      const auto& known = s.known_trainees;
      if (known.empty()) break;
      const auto at = std::find(known.begin(), known.end(), trainee_name(s));
      const size_t i = at == known.end()            ? 0
                       : key == StartKey::kPageDown ? (size_t(at - known.begin()) + 1) % known.size()
                                                    : (size_t(at - known.begin()) + known.size() - 1) % known.size();
      set_trainee_name(s, known[i]);
      break;
    }
    case StartKey::kTab:
      s.focus_name = true;
      break;
    case StartKey::kPractice:
      s.practice = !s.practice;
      break;
    case StartKey::kEnter:
      return try_start(s);
    case StartKey::kEscape:
      return StartAction::kQuit;
  }
  return StartAction::kNone;
}

StartAction draw_start_screen(StartState& s) {
  StartAction action = StartAction::kNone;
  const float em = ImGui::GetFontSize();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = std::min(display.x - 2.0f * em, 62.0f * em);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar;
  if (s.leave_name) {
    ImGui::SetWindowFocus(nullptr);  // ends the field's editing before it sees the key (an Escape would undo the name)
    s.leave_name = false;
  }
  if (ImGui::Begin("Start", nullptr, flags)) {
    ImGui::TextUnformatted("needle-sim: needle insertion training");
    ImGui::Separator();

    section("Trainee", "(Tab: type a name   Page Up/Down: one from earlier sessions)");
    ImGui::SetNextItemWidth(20.0f * em);
    if (s.focus_name) {
      ImGui::SetKeyboardFocusHere();
      s.focus_name = false;
    }
    ImGui::InputTextWithHint("##trainee", "your name", s.trainee.data(), s.trainee.size());
    if (!s.known_trainees.empty()) {
      ImGui::SameLine();
      ImGui::SetNextItemWidth(14.0f * em);
      if (ImGui::BeginCombo("##known", "earlier trainees")) {
        for (const std::string& name : s.known_trainees)
          if (ImGui::Selectable(name.c_str(), name == trainee_name(s))) set_trainee_name(s, name);
        ImGui::EndCombo();
      }
    }
    ImGui::Separator();

    section("Task", "(Up/Down)");
    if (s.tasks.empty()) ImGui::TextColored(kBad, "No task found in the assets folder.");
    for (size_t i = 0; i < s.tasks.size(); ++i) {
      const StartTask& t = s.tasks[i];
      ImGui::PushID(int(i));
      if (ImGui::Selectable(t.title.empty() ? "(a task file that does not load)" : t.title.c_str(), s.task == i))
        s.task = i;
      ImGui::Indent(em);
      if (!t.error.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(kBad, "%s", t.error.c_str());
        ImGui::PopTextWrapPos();
      } else {
        if (!t.description.empty()) ImGui::TextWrapped("%s", t.description.c_str());
        if (t.record) {
          ImGui::TextColored(kGood, "%s", t.record->c_str());
        } else {
          ImGui::TextColored(kDim, "not done yet");
        }
      }
      ImGui::Unindent(em);
      ImGui::PopID();
    }
    ImGui::Separator();

    section("Device", "(Left/Right)");
    for (size_t i = 0; i < s.devices.size(); ++i) {
      const StartDevice& d = s.devices[i];
      if (i > 0) ImGui::SameLine();
      ImGui::BeginDisabled(!d.available);
      if (ImGui::RadioButton(d.label.c_str(), s.device == i)) s.device = i;
      ImGui::EndDisabled();
    }
    if (!s.devices.empty()) ImGui::TextColored(kDim, "%s", s.devices[s.device].help.c_str());
    ImGui::Separator();

    ImGui::Checkbox("Practice (P): the steps without time limits", &s.practice);
    ImGui::Spacing();
    const std::string why = cannot_start(s);
    ImGui::BeginDisabled(!why.empty());
    if (ImGui::Button("Start (Enter)", ImVec2(10.0f * em, 0.0f))) action = try_start(s);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Quit (Esc)", ImVec2(10.0f * em, 0.0f))) action = StartAction::kQuit;
    if (!s.notice.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(kBad, "%s", s.notice.c_str());
      ImGui::PopTextWrapPos();
    } else if (!why.empty()) {
      ImGui::TextColored(kDim, "%s", why.c_str());
    }
  }
  ImGui::End();
  return action;
}

}  // namespace needle::ui
