#include "core/scene_file/json_parse.h"

#include <algorithm>
#include <set>
#include <vector>

#include "core/scene_file/scene_error.h"

namespace wt {
namespace {


// nlohmann keeps only the last of repeated keys, without a word. A repeated material name would
// silently drop a material, so repeats are caught while parsing. Tracking the path also lets an
// overflowing number literal (which nlohmann reports without a position) be placed.
class ParseTracker {
public:
    bool on_event(Json::parse_event_t event, const Json& parsed, const std::string& source) {
        switch (event) {
        case Json::parse_event_t::object_start: frames_.push_back({true, {}, {}, 0}); break;
        case Json::parse_event_t::array_start: frames_.push_back({false, {}, {}, 0}); break;
        case Json::parse_event_t::key: {
            Frame& frame = frames_.back();
            const std::string key = parsed.get<std::string>();
            if (!frame.keys.insert(key).second) {
                const std::string parent = path_of_parent();
                const std::string what = parent == "materials" ? "duplicate material name " + Json(key).dump()
                                                               : "duplicate key " + Json(key).dump();
                throw SceneError(source + ": " + member_path(parent, key) + ": " + what +
                                 " (each key may appear only once in an object)");
            }
            frame.key = key;
            break;
        }
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            frames_.pop_back();
            element_done();
            break;
        case Json::parse_event_t::value: element_done(); break;
        }
        return true;
    }

    // The path of the value being parsed right now.
    std::string current_path() const {
        std::string path;
        for (const Frame& frame : frames_)
            path = frame.is_object ? member_path(path, frame.key) : element_path(path, frame.index);
        return path;
    }

private:
    struct Frame {
        bool is_object;
        std::set<std::string> keys;  // objects: keys seen so far
        std::string key;             // objects: key of the member being parsed
        std::size_t index;           // arrays: index of the element being parsed
    };

    std::string path_of_parent() const {
        std::string path;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
            path = frames_[i].is_object ? member_path(path, frames_[i].key)
                                        : element_path(path, frames_[i].index);
        return path;
    }

    void element_done() {
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
    }

    std::vector<Frame> frames_;
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
    ParseTracker tracker;
    const Json::parser_callback_t callback = [&](int, Json::parse_event_t event, Json& parsed) {
        return tracker.on_event(event, parsed, source);
    };
    try {
        return Json::parse(text, callback);
    } catch (const Json::parse_error& e) {
        throw SceneError(source + ":" + line_and_column(text, e.byte) +
                         ": JSON syntax error: " + strip_nlohmann_prefix(e.what()));
    } catch (const Json::out_of_range& e) {
        // A literal such as 1e999, the only out_of_range the parser raises (406): "number
        // overflow parsing '1e999'". It comes without a position, but the tracker knows the path.
        const std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        const std::string literal = open < close ? what.substr(open + 1, close - open - 1) : what;
        const std::string path = tracker.current_path();
        throw SceneError(source + ": " + (path.empty() ? "(top level)" : path) + ": must be a finite number, got " +
                         literal + " (too large for a double)");
    }
}

}  // namespace wt
