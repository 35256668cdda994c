#pragma once
// Text from a file or an argument, made safe to put in a message: bytes outside printable ASCII
// become \xNN, so a message never sends raw bytes (an escape sequence, half a UTF-8 character)
// to the user's terminal.

#include <cstdio>
#include <string>

namespace wt {

inline std::string printable(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const unsigned char c : text) {
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
        } else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    return out;
}

}  // namespace wt
