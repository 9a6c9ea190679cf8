// Line-oriented reader for OBJ and MTL: whitespace tokens, '#' comments, CRLF and a UTF-8 byte
// order mark tolerated, and errors that name the file and the line.
#pragma once

#include "shared/lang.h"
#include "util/error.h"

#include <fstream>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace tp {

// The most characters of the input an error message quotes: a 200 MB token must not make a
// 200 MB message.
constexpr size_t kMaxQuoted = 80;

// s, or its first kMaxQuoted characters and how many more there are.
std::string clip(std::string_view s);

template <typename T>
decltype(auto) clipped(T&& v) {
    if constexpr (std::is_convertible_v<const T&, std::string_view>)
        return clip(std::string_view(v));
    else
        return std::forward<T>(v);
}

class LineReader {
  public:
    explicit LineReader(std::string path);

    // Reads the next line that has tokens; false at the end of the file.
    bool next(std::vector<std::string_view>& tokens);

    size_t line() const { return line_no_; }
    const std::string& path() const { return path_; }

    // Text from the file among args is quoted by at most kMaxQuoted characters (clip).
    template <typename... Args>
    [[noreturn]] void fail(fmt::format_string<Args...> f, Args&&... args) const {
        throw InputError(fmt::format(
            "{}:{}: {}", path_, line_no_,
            fmt::format(fmt::runtime(fmt::string_view(f)), clipped(std::forward<Args>(args))...)));
    }

    // Strict conversions: the whole token must be a number.
    float parse_number(std::string_view s) const;
    // A coordinate of a position, kept in double (scene/scene.h) but within float's range.
    double parse_coordinate(std::string_view s) const;
    long long parse_integer(std::string_view s) const;

    float number(const std::vector<std::string_view>& tok, size_t i) const;
    long long integer(const std::vector<std::string_view>& tok, size_t i) const;
    vec3 vec3_at(const std::vector<std::string_view>& tok, size_t i) const;
    glm::dvec3 position_at(const std::vector<std::string_view>& tok, size_t i) const;
    // "K r g b" or the grey shorthand "K v".
    vec3 color(const std::vector<std::string_view>& tok) const;
    // The text of the current line after its first n tokens, trimmed (names with spaces).
    std::string rest_after(size_t n) const;

  private:
    std::string path_;
    std::ifstream file_;
    std::string buffer_;
    std::vector<std::string_view> tokens_;
    size_t line_no_ = 0;
};

} // namespace tp
