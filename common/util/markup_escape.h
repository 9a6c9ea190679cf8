// Escapes text for HTML and XML (element content and double-quoted attributes): the compare
// report's index.html and the bench's SVG plots.
#pragma once

#include <string>

namespace tp {

inline std::string markup_escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

} // namespace tp
