// A base for nlohmann's SAX interface that accepts every event, so that a handler overrides only
// the events it looks at (json_loader.cpp, json_duplicate_keys.cpp). A parse error stops.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace tp {

struct JsonSaxAcceptAll : nlohmann::json::json_sax_t {
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return true; }
    bool key(string_t&) override { return true; }
    bool end_object() override { return true; }
    bool start_array(std::size_t) override { return true; }
    bool end_array() override { return true; }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false;
    }
};

} // namespace tp
