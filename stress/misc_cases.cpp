// Cases on the film itself and on the loader.
#include "stress/common.h"

#include "util/output_file.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace tp::stress {

// The double-precision film (common/render/film.h) fed directly, as the CPU engine feeds it
// (add_sample, Welford) and as the GPU's per-pixel double sums arrive (add_batch, Chan et
// al.). Constant samples: the mean must be the sample to 1e-6 relative after N of them and the
// variance exactly >= 0; a 1e6 firefly in one pixel leaves the others untouched; and a pixel
// whose mean is 1e3 times its spread keeps its variance to 1e-3 relative.
std::vector<CaseResult> film_accumulation_cases(const Size& s) {
    std::vector<CaseResult> out;
    const uint64_t n = s.accumulation_spp;
    const double x = double(0.3f);
    CaseResult c;
    c.group = "accumulation";
    c.backend = "c++";
    c.mode = "film";
    c.name = fmt::format("film: {} constant samples (Welford and batched sums)", n);
    c.expected = "mean = sample to 1e-6 relative, variance >= 0 and <= 1e-20";
    out.push_back(timed(c, [&](CaseResult& r) {
        Film f(3, 1);
        for (uint64_t k = 0; k < n; ++k) f.add_sample(0, glm::dvec3(x));
        // Batches of 4096 as a GPU dispatch delivers them: double sum and sum of squares.
        const uint64_t batch = 4096;
        for (uint64_t k = 0; k < n; k += batch) {
            const uint64_t m = std::min(batch, n - k);
            double sum = 0.0, sum_sq = 0.0;
            for (uint64_t j = 0; j < m; ++j) sum += x, sum_sq += x * x;
            f.add_batch(1, m, glm::dvec3(sum), glm::dvec3(sum_sq));
        }
        double worst = 0.0, vmin = 1e300, vmax = 0.0;
        for (uint32_t p = 0; p < 2; ++p) {
            worst = std::max(worst, std::abs(f.mean(p).x / x - 1.0));
            vmin = std::min(vmin, cmin(f.variance_of_mean(p)));
            vmax = std::max(vmax, cmax(f.variance_of_mean(p)));
            r.nan += !std::isfinite(f.mean(p).x);
        }
        r.checked = 2 * n;
        r.pass =
            worst <= 1e-6 && vmin >= 0.0 && vmax <= 1e-20 && f.count(0) == n && f.count(1) == n;
        r.measured = fmt::format("worst relative error {:.2g}, variance in [{:.2g}, {:.2g}]", worst,
                                 vmin, vmax);
    }));
    c.name = "film: 1e6 firefly beside constant pixels";
    c.expected = "neighbours' means exactly 0.3f, their variance 0";
    out.push_back(timed(c, [&](CaseResult& r) {
        Film f(3, 3);
        for (uint64_t k = 0; k < 4096; ++k)
            for (uint32_t p = 0; p < 9; ++p)
                f.add_sample(p, glm::dvec3(p == 4 && k == 17 ? 1e6 : x));
        double worst = 0.0, var = 0.0;
        for (uint32_t p = 0; p < 9; ++p) {
            if (p == 4) continue;
            worst = std::max(worst, std::abs(f.mean(p).x - x));
            var = std::max(var, cmax(f.variance_of_mean(p)));
        }
        r.checked = 9 * 4096;
        r.pass = worst == 0.0 && var == 0.0 && f.mean(4).x > 200.0;
        r.measured = fmt::format("neighbours' worst error {:.2g}, variance {:.2g}; centre {:.6g}",
                                 worst, var, f.mean(4).x);
    }));
    c.name = "film: mean 1e3 x its spread";
    c.expected = "variance of the samples 1 to 1e-3 relative (no cancellation), never negative";
    out.push_back(timed(c, [&](CaseResult& r) {
        // Samples 1000 +- 1 alternately: sample variance exactly n / (n - 1).
        Film f(2, 1);
        const uint64_t m = n - n % 2;
        for (uint64_t k = 0; k < m; ++k) f.add_sample(0, glm::dvec3(k % 2 ? 1001.0 : 999.0));
        for (uint64_t k = 0; k < m; k += 4096) {
            const uint64_t b = std::min<uint64_t>(4096, m - k);
            double sum = 0.0, sum_sq = 0.0;
            for (uint64_t j = 0; j < b; ++j) {
                const double v = (k + j) % 2 ? 1001.0 : 999.0;
                sum += v;
                sum_sq += v * v;
            }
            f.add_batch(1, b, glm::dvec3(sum), glm::dvec3(sum_sq));
        }
        const double expect = double(m) / double(m - 1); // sample variance
        double worst = 0.0;
        for (uint32_t p = 0; p < 2; ++p)
            worst = std::max(worst, std::abs(f.variance_of_mean(p).x * double(m) / expect - 1.0));
        r.checked = 2 * m;
        r.pass = worst <= 1e-3;
        r.measured = fmt::format("worst relative error of the variance {:.2g}", worst);
    }));
    return out;
}

CaseResult nan_vertex_case(const std::string& twinpath_binary, const std::string& temp_dir) {
    CaseResult c;
    c.group = "degenerate";
    c.name = "NaN vertex in an OBJ";
    c.backend = "cpu";
    c.mode = "loader";
    c.expected = "rejected at load: exit code 2, an error naming the file and line, no image";
    return timed(c, [&](CaseResult& r) {
        fs::create_directories(temp_dir);
        const fs::path obj = fs::path(temp_dir) / "nan_vertex.obj";
        const fs::path exr = fs::path(temp_dir) / "nan_vertex.exr";
        write_output_file(obj.string(), "v 0 0 0\nv 1 0 0\nv nan 1 0\nv 0 1 0\nf 1 2 4\nf 2 3 4\n");
        fs::remove(exr);
        const std::string log = (fs::path(temp_dir) / "nan_vertex.log").string();
        const std::string cmd = fmt::format("'{}' render '{}' -o '{}' --spp 1 --width 4 --height 4 "
                                            ">'{}' 2>&1",
                                            twinpath_binary, obj.string(), exr.string(), log);
        const int status = std::system(cmd.c_str());
        const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        std::ifstream in(log);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
        const bool names = text.find("nan_vertex.obj") != std::string::npos &&
                           text.find("not finite") != std::string::npos;
        r.checked = 1;
        r.pass = code == 2 && names && !fs::exists(exr);
        r.measured = fmt::format("exit {}, message: {}", code, text);
    });
}

} // namespace tp::stress
