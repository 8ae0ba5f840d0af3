#include "ui/wrapped_text.hpp"

#include <cstdarg>

namespace needle::ui {

void wrapped_text(const ImVec4& colour, const char* format, ...) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  va_list args;
  va_start(args, format);
  ImGui::TextWrappedV(format, args);
  va_end(args);
  ImGui::PopStyleColor();
}

}  // namespace needle::ui
