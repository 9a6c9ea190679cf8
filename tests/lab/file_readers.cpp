#include "file_readers.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tp::test {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

namespace {

// The fields of each record: a quoted field may hold commas, newlines and doubled quotes.
std::vector<std::vector<std::string>> csv_records(const std::string& text) {
    if (text.empty() || text.back() != '\n') throw std::runtime_error("CSV: no final newline");
    std::vector<std::vector<std::string>> records(1);
    std::string field;
    bool quoted = false, was_quoted = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c != '"')
                field += c;
            else if (i + 1 < text.size() && text[i + 1] == '"')
                field += text[++i];
            else
                quoted = false;
        } else if (c == '"') {
            if (!field.empty() || was_quoted) throw std::runtime_error("CSV: stray quote");
            quoted = was_quoted = true;
        } else if (c == ',' || c == '\n') {
            records.back().push_back(field);
            field.clear();
            was_quoted = false;
            if (c == '\n' && i + 1 < text.size()) records.emplace_back();
        } else {
            if (was_quoted) throw std::runtime_error("CSV: text after a closing quote");
            field += c;
        }
    }
    if (quoted) throw std::runtime_error("CSV: unterminated quote");
    return records;
}

} // namespace

Csv read_csv(const std::string& path) {
    const std::vector<std::vector<std::string>> records = csv_records(read_file(path));
    Csv csv;
    csv.header = records.front();
    for (size_t r = 1; r < records.size(); ++r) {
        if (records[r].size() != csv.header.size())
            throw std::runtime_error(path + ": row " + std::to_string(r) + " has " +
                                     std::to_string(records[r].size()) + " fields, the header " +
                                     std::to_string(csv.header.size()));
        std::map<std::string, std::string> row;
        for (size_t i = 0; i < csv.header.size(); ++i) row[csv.header[i]] = records[r][i];
        csv.rows.push_back(row);
    }
    return csv;
}

std::map<std::string, int> xml_element_counts(const std::string& text) {
    const auto fail = [](const std::string& what, size_t at) {
        throw std::runtime_error("XML: " + what + " at offset " + std::to_string(at));
    };
    const auto is_name = [](char c) {
        return std::isalnum((unsigned char)c) || c == '-' || c == ':' || c == '_';
    };
    std::map<std::string, int> counts;
    std::vector<std::string> open;
    size_t i = 0, roots = 0;
    if (text.compare(0, 5, "<?xml") == 0) {
        i = text.find("?>");
        if (i == std::string::npos) fail("unterminated declaration", 0);
        i += 2;
    }
    while (i < text.size()) {
        const char c = text[i];
        if (c == '&') {
            const size_t semi = text.find(';', i);
            const std::string entity =
                semi == std::string::npos ? "" : text.substr(i, semi + 1 - i);
            if (entity != "&amp;" && entity != "&lt;" && entity != "&gt;" && entity != "&quot;" &&
                entity != "&apos;")
                fail("unknown entity", i);
            i = semi + 1;
            continue;
        }
        if (c != '<') {
            if (open.empty() && !std::isspace((unsigned char)c)) fail("text outside the root", i);
            ++i;
            continue;
        }
        const bool closing = i + 1 < text.size() && text[i + 1] == '/';
        size_t j = i + (closing ? 2 : 1);
        const size_t name_start = j;
        while (j < text.size() && is_name(text[j])) ++j;
        const std::string name = text.substr(name_start, j - name_start);
        if (name.empty()) fail("tag without a name", i);
        if (closing) {
            if (open.empty() || open.back() != name) fail("</" + name + "> closes nothing open", i);
            open.pop_back();
            if (j >= text.size() || text[j] != '>') fail("bad end tag", i);
            i = j + 1;
            continue;
        }
        // Attributes: name="value" (or 'value'), separated by spaces, then > or />.
        for (;;) {
            while (j < text.size() && std::isspace((unsigned char)text[j])) ++j;
            if (j >= text.size()) fail("unterminated tag", i);
            if (text[j] == '>' || text.compare(j, 2, "/>") == 0) break;
            const size_t a = j;
            while (j < text.size() && is_name(text[j])) ++j;
            if (j == a || j + 1 >= text.size() || text[j] != '=' ||
                (text[j + 1] != '"' && text[j + 1] != '\''))
                fail("attribute without a quoted value", j);
            const size_t end = text.find(text[j + 1], j + 2);
            if (end == std::string::npos ||
                text.substr(j + 2, end - j - 2).find('<') != std::string::npos)
                fail("unterminated attribute value", j);
            j = end + 1;
        }
        if (open.empty() && roots++ > 0) fail("a second root element", i);
        ++counts[name];
        if (text[j] == '>') {
            open.push_back(name);
            i = j + 1;
        } else {
            i = j + 2;
        }
    }
    if (!open.empty()) fail("<" + open.back() + "> is never closed", text.size());
    if (roots != 1) fail("no root element", 0);
    return counts;
}

} // namespace tp::test
