// Readers for the files `twinpath-lab markdown` writes, strict enough to tell a well-formed file
// from a broken one: CSV (RFC 4180 quoting) and XML (well-formedness only: the SVG plots).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace tp::test {

std::string read_file(const std::string& path);

struct Csv {
    std::vector<std::string> header;
    std::vector<std::map<std::string, std::string>> rows; // column name -> field
};

// Throws std::runtime_error for a row whose field count differs from the header's, an
// unterminated quote, or a missing final newline.
Csv read_csv(const std::string& path);

// Checks that `text` is one well-formed XML element (an optional <?xml ...?> declaration first):
// tags nest and close, attribute values are quoted, '&' starts a known entity. Returns the
// number of start tags of each element name; throws std::runtime_error otherwise.
std::map<std::string, int> xml_element_counts(const std::string& text);

} // namespace tp::test
