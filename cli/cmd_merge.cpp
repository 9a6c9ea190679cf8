// twinpath merge A.exr B.exr ... -o OUT.exr: renders of disjoint sample ranges into one image
// (compare/merge.h, docs/farm.md). Exit codes: 0 merged, 2 parts that do not belong together.
#include "commands.h"
#include "output_paths.h"

#include "compare/merge.h"
#include "util/error.h"

#include <fmt/core.h>

namespace tp {

Subcommand add_merge_command(CLI::App& app) {
    auto files = std::make_shared<std::vector<std::string>>();
    auto out = std::make_shared<std::string>();
    auto film = std::make_shared<std::string>("full");
    CLI::App* c = app.add_subcommand("merge", "Merge renders of disjoint sample ranges");
    c->add_option("parts", *files, "The renders (OpenEXR) to merge")->required();
    c->add_option("-o,--output", *out, "Merged OpenEXR file")->required();
    c->add_option("--film", *film,
                  "Output channels: full (the batch means too, to merge again) or lean "
                  "(docs/farm.md)")
        ->check(CLI::IsMember({"lean", "full"}))
        ->capture_default_str();
    return {c, [files, out, film] {
                check_output_paths({{"-o", *out}});
                for (const std::string& f : *files)
                    if (f == *out) input_error("-o {} is also one of the parts", *out);
                const ExrImage merged = merge_files(*files, film_layout_from_name(*film));
                write_exr(*out, merged);
                fmt::print("merged {} parts, {} spp (samples {}) -> {}\n", files->size(),
                           merged.integers.at("twinpath:spp"),
                           merged.strings.at("twinpath:sample_ranges"), *out);
                return 0;
            }};
}

} // namespace tp
