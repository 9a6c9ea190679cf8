#include "scene/json_duplicate_keys.h"

#include "scene/json_sax.h"
#include "scene/text_parse.h"
#include "util/error.h"

#include <nlohmann/json.hpp>

#include <map>
#include <vector>

namespace tp {
namespace {

using json = nlohmann::json;

// Numbers the keys in document order and stops at the first key an object already has.
struct DuplicateKeys : JsonSaxAcceptAll {
    std::vector<std::map<std::string, size_t>> open; // per open object: key -> its number
    size_t keys = 0;
    size_t first = 0, second = 0; // the numbers of the two occurrences, once found
    std::string key_name;

    bool start_object(std::size_t) override {
        open.emplace_back();
        return true;
    }
    bool key(string_t& k) override {
        const size_t n = keys++;
        const auto [it, inserted] = open.back().emplace(k, n);
        if (inserted) return true;
        first = it->second;
        second = n;
        key_name = k;
        return false;
    }
    bool end_object() override {
        open.pop_back();
        return true;
    }
};

// The lines of the keys numbered a and b (document order). A key is the one kind of JSON string
// that a ':' follows, so counting those strings counts the keys.
std::pair<size_t, size_t> key_lines(const std::string& text, size_t a, size_t b) {
    size_t line = 1, key = 0, line_a = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n') ++line;
        if (text[i] != '"') continue;
        const size_t start_line = line;
        for (++i; i < text.size() && text[i] != '"'; ++i)
            if (text[i] == '\\') ++i; // an escape: the next character is part of the string
        size_t j = i + 1;
        while (j < text.size() &&
               (text[j] == ' ' || text[j] == '\t' || text[j] == '\r' || text[j] == '\n'))
            ++j;
        if (j >= text.size() || text[j] != ':') continue;
        if (key == a) line_a = start_line;
        if (key == b) return {line_a, start_line};
        ++key;
    }
    return {line_a, 0};
}

} // namespace

void reject_duplicate_keys(const std::string& path, const std::string& text) {
    DuplicateKeys sax;
    json::sax_parse(text, &sax);
    if (sax.second == 0) return; // no key repeated (a repeat is never key number 0)
    const auto [a, b] = key_lines(text, sax.first, sax.second);
    input_error("{}: key '{}' appears twice in one object, at lines {} and {}", path,
                clip(sax.key_name), a, b);
}

} // namespace tp
