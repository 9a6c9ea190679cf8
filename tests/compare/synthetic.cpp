#include "synthetic.h"

#include "image/exr_io.h"
#include "render/film.h"

#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace tp::test {
namespace {

// `q`: the pixel's caustic probability (Noise::Caustic only); `u` in [0, 1): the uniform
// that drives the distribution (the quantile, or the coin of the rare sample).
double draw(Noise noise, double q, double u, std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    const boost::math::normal standard;
    const double open_u = std::max(u, 0x1p-60); // the normal quantile is -inf at 0
    switch (noise) {
    case Noise::Gaussian:
        return 1.0 + 0.5 * boost::math::quantile(standard, open_u);
    case Noise::Lognormal:
        return std::exp(boost::math::quantile(standard, open_u) - 0.5);
    case Noise::Pareto:
        return 0.6 * std::pow(1.0 - u, -1.0 / 2.5);
    case Noise::Firefly:
        return 0.5 * (1.0 + 0.3 * normal(rng)) + (u < 0.01 ? 50.0 : 0.0);
    case Noise::Caustic:
        return 0.5 * (1.0 + 0.3 * normal(rng)) + (u < q ? 0.5 / q : 0.0);
    }
    return 0.0;
}

} // namespace

double caustic_probability(int x, int y) {
    // A Weyl sequence over the pixel index (golden ratio) scatters the exponents.
    const double u = std::fmod(double(y * 4099 + x) * 0.6180339887498949, 1.0);
    return std::pow(10.0, -4.0 + 3.0 * u);
}

double true_mean(const SyntheticSpec& s, int channel, int x, int y) {
    if (x < 2) return 0.0;
    const double u = (x + 0.5) / s.width, v = (y + 0.5) / s.height;
    const double tint[3] = {0.9, 0.6, 0.3};
    return tint[channel] * (0.2 + 0.8 * u * (1.0 - 0.5 * v));
}

RgbImage synthetic_render(const SyntheticSpec& s, uint64_t seed, const Bias& bias) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> uniform;
    Film film(uint32_t(s.width), uint32_t(s.height), s.batches);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const bool in = x >= bias.x0 && x < bias.x1 && y >= bias.y0 && y < bias.y1;
            const double k = in ? bias.scale : 1.0;
            const glm::dvec3 mu(k * true_mean(s, 0, x, y), k * true_mean(s, 1, x, y),
                                k * true_mean(s, 2, x, y));
            const uint32_t p = uint32_t(y * s.width + x);
            const double q = caustic_probability(x, y);
            // Sample i is the (i / K)-th of its batch i mod K, which holds n_b samples.
            auto u = [&](uint32_t i) {
                if (s.batches == 0) return uniform(rng);
                const uint32_t k = s.batches, b = i % k;
                const uint32_t n_b = s.spp / k + (b < s.spp % k ? 1 : 0);
                return (double(i / k) + uniform(rng)) / double(n_b);
            };
            for (uint32_t i = 0; i < s.spp; ++i) {
                glm::dvec3 yv;
                yv.x = draw(s.noise, q, u(i), rng);
                yv.y = s.correlated_channels ? yv.x : draw(s.noise, q, u(i), rng);
                yv.z = s.correlated_channels ? yv.x : draw(s.noise, q, u(i), rng);
                film.add_sample(p, mu * yv, i);
            }
        }
    ExrImage img = film.to_exr();
    img.integers["twinpath:spp"] = s.spp;
    return rgb_image_from_exr(img, "synthetic-" + std::to_string(seed));
}

RgbImage synthetic_reference(const SyntheticSpec& s) {
    RgbImage r;
    r.path = "synthetic-truth";
    r.width = s.width;
    r.height = s.height;
    for (int c = 0; c < 3; ++c) {
        auto& m = r.mean[size_t(c)];
        m.resize(r.pixels());
        // float32 like every EXR value
        for (int y = 0; y < s.height; ++y)
            for (int x = 0; x < s.width; ++x)
                m[size_t(y * s.width + x)] = double(float(true_mean(s, c, x, y)));
    }
    return r;
}

} // namespace tp::test
