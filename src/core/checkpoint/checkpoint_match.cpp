#include "core/checkpoint/checkpoint_match.h"

#include "core/description/scene_hash.h"

namespace wt {

FilmLayout layout_of(const Film& film) { return {film.width(), film.height(), film.extra_channels()}; }

namespace {

std::string joined(const std::vector<std::string>& names) {
    if (names.empty()) return "(none)";
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ",") + n;
    return s;
}

std::string size_of(const FilmLayout& l) { return std::to_string(l.width) + "x" + std::to_string(l.height); }

}  // namespace

std::vector<std::string> checkpoint_differences(const CheckpointHeader& a, const FilmLayout& a_layout,
                                                const std::string& a_label, const CheckpointHeader& b,
                                                const FilmLayout& b_layout, const std::string& b_label) {
    std::vector<std::string> lines;
    if (a.program_version != b.program_version)
        lines.push_back("program version: " + a_label + " " + a.program_version + ", " + b_label + " " + b.program_version);
    if (a.scene_hash != b.scene_hash)
        lines.push_back("scene content (camera, materials or geometry): " + a_label + " hash " + hash_to_hex(a.scene_hash) +
                        ", " + b_label + " hash " + hash_to_hex(b.scene_hash));
    if (a_layout.width != b_layout.width || a_layout.height != b_layout.height)
        lines.push_back("size: " + a_label + " " + size_of(a_layout) + ", " + b_label + " " + size_of(b_layout));
    if (a_layout.extra_channels != b_layout.extra_channels)
        lines.push_back("extra channels: " + a_label + " " + joined(a_layout.extra_channels) + ", " + b_label + " " +
                        joined(b_layout.extra_channels));
    for (std::string& line : setting_differences(a.settings, a_label, b.settings, b_label)) lines.push_back(std::move(line));
    return lines;
}

std::string describe_differences(const std::string& lead, const std::vector<std::string>& lines) {
    std::string s = lead + ": ";
    for (std::size_t i = 0; i < lines.size(); ++i) s += (i ? "; " : "") + lines[i];
    return s;
}

}  // namespace wt
