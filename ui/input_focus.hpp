// Whether the panels hold the pointer or the keyboard this frame: the application's own input
// (a desk device, the window's keys) leaves them alone then. False outside a UI frame.
#pragma once

namespace needle::ui {

// The pointer is over a panel, whose clicks and motion are the panel's.
bool pointer_on_panel();
// A text field has the keyboard.
bool typing();

}  // namespace needle::ui
