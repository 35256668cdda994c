#include "core/scene_file/json_parse.h"

#include <algorithm>
#include <unordered_set>
#include <vector>

#include "core/base/printable.h"
#include "core/scene_file/scene_error.h"

namespace wt {
namespace {

// Builds the ordered_json tree from nlohmann's SAX events ourselves, for three reasons a user
// of a hostile file would otherwise meet:
// - Depth: a JSON value nested 80,000 deep is legal JSON, but printing it (dump(), describe())
//   recurses once per level and overflows the stack. No scene needs more than a few levels.
// - Time: ordered_json's object insert searches the keys so far (a 40k-key object took 5 s);
//   repeats are caught here with a hash set, so members are appended without the search.
// - Repeats: nlohmann keeps only the last of repeated keys, without a word; a repeated
//   material name would silently drop a material.
// The path of the value being parsed is kept as one frame per open container, so a message can
// name it at any point (an overflowing number, too deep a nesting) in time linear in the depth.
class ScenePathBuilder {
public:
    ScenePathBuilder(Json& root, const std::string& source) : root_(root), source_(source) {}

    bool null() { return scalar(Json(nullptr)); }
    bool boolean(bool v) { return scalar(Json(v)); }
    bool number_integer(Json::number_integer_t v) { return scalar(Json(v)); }
    bool number_unsigned(Json::number_unsigned_t v) { return scalar(Json(v)); }
    bool number_float(Json::number_float_t v, const std::string&) { return scalar(Json(v)); }
    bool string(std::string& v) { return scalar(Json(std::move(v))); }
    bool binary(Json::binary_t& v) { return scalar(Json(std::move(v))); }

    bool start_object(std::size_t) { return open(Json::object()); }
    bool start_array(std::size_t) { return open(Json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(std::string& key) {
        Frame& frame = frames_.back();
        if (!frame.keys.insert(key).second) {
            const std::string parent = path(frames_.size() - 1);
            const std::string what = parent == "materials" ? "duplicate material name " + Json(key).dump()
                                                           : "duplicate key " + Json(key).dump();
            throw SceneError(source_ + ": " + member_path(parent, key) + ": " + what +
                             " (each key may appear only once in an object)");
        }
        frame.key = key;
        return true;
    }

    bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) {
        error_byte_ = byte;
        error_id_ = e.id;
        error_what_ = e.what();
        return false;
    }

    std::size_t error_byte() const { return error_byte_; }  // 1-based, as nlohmann counts
    int error_id() const { return error_id_; }
    const std::string& error_what() const { return error_what_; }

    // The path of the value being parsed right now ("" at the top level).
    std::string current_path() const { return path(frames_.size()); }

private:
    struct Frame {
        Json* value;
        std::unordered_set<std::string> keys;  // objects: keys seen so far
        std::string key;                       // objects: key of the member being parsed
        std::size_t index = 0;                 // arrays: index of the element being parsed
    };

    // The path of the value inside the first `depth` open containers.
    std::string path(std::size_t depth) const {
        std::string p;
        for (std::size_t i = 0; i < depth; ++i)
            p = frames_[i].value->is_object() ? member_path(p, frames_[i].key) : element_path(p, frames_[i].index);
        return p;
    }

    // Appends without ordered_map's search for an existing key: key() has ruled repeats out.
    // Pointers into a container stay valid while it is open, since only its last child grows.
    Json* add(Json&& v) {
        if (frames_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        Frame& frame = frames_.back();
        Json& parent = *frame.value;
        if (parent.is_array()) {
            auto& elements = parent.get_ref<Json::array_t&>();
            elements.push_back(std::move(v));
            return &elements.back();
        }
        auto& members = static_cast<std::vector<std::pair<const std::string, Json>>&>(parent.get_ref<Json::object_t&>());
        members.emplace_back(frame.key, std::move(v));
        return &members.back().second;
    }

    bool open(Json&& container) {
        if (frames_.size() >= kMaxJsonDepth) {
            const std::string at = current_path();
            throw SceneError(source_ + ": " + (at.empty() ? "(top level)" : at) + ": JSON nested deeper than " +
                             std::to_string(kMaxJsonDepth) + " levels (no scene needs more than a few)");
        }
        Json* value = add(std::move(container));
        frames_.push_back(Frame{value, {}, {}, 0});
        return true;
    }

    bool close() {
        frames_.pop_back();
        element_done();
        return true;
    }

    bool scalar(Json&& v) {
        add(std::move(v));
        element_done();
        return true;
    }

    void element_done() {
        if (!frames_.empty()) ++frames_.back().index;
    }

    Json& root_;
    const std::string& source_;
    std::vector<Frame> frames_;
    std::size_t error_byte_ = 0;
    int error_id_ = 0;
    std::string error_what_;
};

// nlohmann's line/column is that of the last character it read, which can be a newline
// ("line 2, column 0"); report the position of the offending character instead.
std::string line_and_column(const std::string& text, std::size_t byte) {
    const std::size_t offset = std::min(byte > 0 ? byte - 1 : 0, text.size());  // byte is 1-based
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            line_start = i + 1;
        }
    }
    return std::to_string(line) + ":" + std::to_string(offset - line_start + 1);
}

// "[json.exception.parse_error.101] parse error at line 2, column 8: syntax error while parsing
// value - unexpected ','" -> "while parsing value - unexpected ','"
std::string strip_nlohmann_prefix(const std::string& what) {
    std::string msg = what;
    const std::size_t colon = msg.find(": ");
    if (colon != std::string::npos) msg = msg.substr(colon + 2);
    const std::string redundant = "syntax error ";
    if (msg.compare(0, redundant.size(), redundant) == 0) msg = msg.substr(redundant.size());
    return msg;
}

}  // namespace

Json parse_json(const std::string& text, const std::string& source) {
    Json root;
    ScenePathBuilder builder(root, source);
    const bool ok = Json::sax_parse(text, &builder, Json::input_format_t::json, true, false);
    if (ok) return root;
    // 406: a literal such as 1e999, too large for a double: "number overflow parsing '1e999'".
    // It comes without a useful position, but the builder knows the path.
    const std::string& what = builder.error_what();
    if (builder.error_id() == 406) {
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        const std::string literal = open < close ? what.substr(open + 1, close - open - 1) : what;
        const std::string path = builder.current_path();
        throw SceneError(source + ": " + (path.empty() ? "(top level)" : path) + ": must be a finite number, got " +
                         printable(literal) + " (too large for a double)");
    }
    // The message quotes the bytes it stopped at, which may be anything the file holds.
    throw SceneError(source + ":" + line_and_column(text, builder.error_byte()) + ": JSON syntax error: " +
                     printable(strip_nlohmann_prefix(what)));
}

}  // namespace wt
