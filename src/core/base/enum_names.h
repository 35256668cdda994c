#pragma once
// Parsing a setting's text back into its enum, by the same name_of() that prints it, so the
// names a scene file accepts and the names the renderer reports can never drift apart.

#include <initializer_list>
#include <optional>
#include <string>

namespace wt {

template <typename Enum>
std::optional<Enum> parse_one_of(const std::string& text, std::initializer_list<Enum> values) {
    for (Enum v : values)
        if (text == name_of(v)) return v;
    return std::nullopt;
}

}  // namespace wt
