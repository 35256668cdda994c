#pragma once
// The words of one line of a text mesh format, and the numbers they spell, read strictly: a
// word that is not a number is reported, never read as 0 (tinyobjloader's habit, which is why
// OBJ has its own reader).

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <system_error>

namespace wt {

inline bool is_blank(char c) { return c == ' ' || c == '\t'; }

// Blank-separated words; a word starting with '#' ends the line (a trailing comment).
class TextWords {
public:
    explicit TextWords(std::string_view line) : rest_(line) {}

    // The next word, or an empty view at the end of the line.
    std::string_view next() {
        std::size_t start = 0;
        while (start < rest_.size() && is_blank(rest_[start])) ++start;
        std::size_t end = start;
        while (end < rest_.size() && !is_blank(rest_[end])) ++end;
        std::string_view word = rest_.substr(start, end - start);
        rest_.remove_prefix(end);
        if (!word.empty() && word[0] == '#') {
            rest_ = {};
            return {};
        }
        return word;
    }

    // What is left of the line, without leading and trailing blanks (a name may hold spaces).
    std::string_view rest() const {
        std::string_view r = rest_;
        while (!r.empty() && is_blank(r.front())) r.remove_prefix(1);
        while (!r.empty() && is_blank(r.back())) r.remove_suffix(1);
        return r;
    }

private:
    std::string_view rest_;
};

// A decimal (or "inf"/"nan") number filling the whole word, as strtod reads it: in double, so
// the same text gives the same float here as in a scene file's JSON (rounded once more to
// float by the caller). Overflow gives an infinity and underflow a value towards 0, for the
// caller's finiteness check to judge; false if the word is not a number.
inline bool parse_real(std::string_view word, double& out) {
    if (!word.empty() && word[0] == '+') word.remove_prefix(1);
    if (word.empty() || word[0] == '+') return false;
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(word.data(), end, out);
    if (ptr != end) return false;  // also for invalid_argument: ptr is then the first character
    // from_chars leaves `out` alone when the value is out of range; strtod says which way.
    if (ec == std::errc::result_out_of_range) out = std::strtod(std::string(word).c_str(), nullptr);
    return true;
}

// A decimal integer filling the whole word (an optional sign, then digits).
enum class IntegerWord { ok, not_an_integer, out_of_range };
inline IntegerWord parse_integer(std::string_view word, int64_t& out) {
    if (!word.empty() && word[0] == '+') word.remove_prefix(1);
    if (word.empty() || word[0] == '+') return IntegerWord::not_an_integer;
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(word.data(), end, out);
    if (ec == std::errc::result_out_of_range && ptr == end) return IntegerWord::out_of_range;
    if (ec != std::errc() || ptr != end) return IntegerWord::not_an_integer;
    return IntegerWord::ok;
}

}  // namespace wt
