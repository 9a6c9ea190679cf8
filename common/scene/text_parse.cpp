#include "scene/text_parse.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

namespace tp {

std::string clip(std::string_view s) {
    if (s.size() <= kMaxQuoted) return std::string(s);
    return fmt::format("{}... ({} more bytes)", s.substr(0, kMaxQuoted), s.size() - kMaxQuoted);
}

LineReader::LineReader(std::string path) : path_(std::move(path)) {
    std::error_code ec;
    if (std::filesystem::is_directory(path_, ec))
        input_error("{}: is a directory, not a file", path_);
    file_.open(path_);
    if (!file_) input_error("{}: cannot open file: {}", path_, std::strerror(errno));
}

bool LineReader::next(std::vector<std::string_view>& tokens) {
    while (std::getline(file_, buffer_)) {
        ++line_no_;
        // A UTF-8 byte order mark, as some editors write, as the JSON loader accepts it.
        if (line_no_ == 1 && buffer_.rfind("\xEF\xBB\xBF", 0) == 0) buffer_.erase(0, 3);
        const size_t hash = buffer_.find('#');
        if (hash != std::string::npos) buffer_.resize(hash);
        tokens.clear();
        const std::string_view s(buffer_);
        size_t i = 0;
        while (i < s.size()) {
            while (i < s.size() && std::isspace((unsigned char)s[i])) ++i;
            const size_t start = i;
            while (i < s.size() && !std::isspace((unsigned char)s[i])) ++i;
            if (i > start) tokens.push_back(s.substr(start, i - start));
        }
        if (!tokens.empty()) {
            tokens_ = tokens;
            return true;
        }
    }
    if (file_.bad()) input_error("{}:{}: read error", path_, line_no_);
    return false;
}

float LineReader::parse_number(std::string_view s) const {
    float v = 0.0f;
    const char* end = s.data() + s.size();
    const char* begin = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
    auto [ptr, ec] = std::from_chars(begin, end, v);
    if (ec == std::errc::result_out_of_range) fail("number '{}' is out of float range", s);
    if (ec != std::errc() || ptr != end) fail("'{}' is not a number", s);
    return v;
}

double LineReader::parse_coordinate(std::string_view s) const {
    double v = 0.0;
    const char* end = s.data() + s.size();
    const char* begin = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
    auto [ptr, ec] = std::from_chars(begin, end, v);
    if (ec == std::errc::result_out_of_range) fail("number '{}' is out of float range", s);
    if (ec != std::errc() || ptr != end) fail("'{}' is not a number", s);
    if (std::isfinite(v) && std::abs(v) > double(std::numeric_limits<float>::max()))
        fail("number '{}' is out of float range", s);
    return v;
}

long long LineReader::parse_integer(std::string_view s) const {
    long long v = 0;
    const char* end = s.data() + s.size();
    auto [ptr, ec] = std::from_chars(s.data(), end, v);
    if (ec != std::errc() || ptr != end) fail("'{}' is not an integer", s);
    return v;
}

float LineReader::number(const std::vector<std::string_view>& tok, size_t i) const {
    if (i >= tok.size()) fail("'{}' needs {} value(s)", tok[0], i);
    const float v = parse_number(tok[i]);
    if (!std::isfinite(v)) fail("'{}' value '{}' is not finite", tok[0], tok[i]);
    return v;
}

long long LineReader::integer(const std::vector<std::string_view>& tok, size_t i) const {
    if (i >= tok.size()) fail("'{}' needs {} value(s)", tok[0], i);
    return parse_integer(tok[i]);
}

vec3 LineReader::vec3_at(const std::vector<std::string_view>& tok, size_t i) const {
    if (i + 2 >= tok.size()) fail("'{}' needs 3 values", tok[0]);
    return vec3(parse_number(tok[i]), parse_number(tok[i + 1]), parse_number(tok[i + 2]));
}

vec3 LineReader::color(const std::vector<std::string_view>& tok) const {
    if (tok.size() == 2) return vec3(number(tok, 1));
    if (tok.size() != 4) fail("'{}' needs 3 values (r g b), got {}", tok[0], tok.size() - 1);
    return vec3(number(tok, 1), number(tok, 2), number(tok, 3));
}

glm::dvec3 LineReader::position_at(const std::vector<std::string_view>& tok, size_t i) const {
    if (i + 2 >= tok.size()) fail("'{}' needs 3 values", tok[0]);
    return glm::dvec3(parse_coordinate(tok[i]), parse_coordinate(tok[i + 1]),
                      parse_coordinate(tok[i + 2]));
}

std::string LineReader::rest_after(size_t n) const {
    if (n >= tokens_.size()) return {};
    const char* begin = tokens_[n].data();
    const char* end = tokens_.back().data() + tokens_.back().size();
    return std::string(begin, end);
}

} // namespace tp
