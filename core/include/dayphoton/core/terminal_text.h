// Text from input files and command lines printed in messages must not drive the terminal:
// a file name or a line of a wrongly named file may hold escape sequences (ESC [ ... m,
// OSC titles, a bell) or bytes that are not UTF-8. printable_text() shows them as C-style
// escapes instead, keeping valid UTF-8 (accented names) as it is.
#pragma once

#include <string>
#include <string_view>

namespace dayphoton {

/// `text` with every control character except tab (0x00-0x1F, 0x7F, and the C1 controls
/// U+0080-U+009F), and every byte that is not part of valid UTF-8, written as "\xNN"
/// ("\n", "\r" and "\e" for the common ones).
std::string printable_text(std::string_view text);

}  // namespace dayphoton
