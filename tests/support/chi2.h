// Chi-square goodness-of-fit tests of sampling routines, in the manner of Mitsuba 3's chi2.py
// and pbrt-v4's src/pbrt/bsdfs_test.cpp: samples are binned on a grid over the domain, the
// expected count of every cell is the pdf integrated over the cell by adaptive quadrature,
// cells that expect fewer than 5 samples are pooled, and Pearson's statistic is referred to
// the chi-square distribution.
//
// Where the samples come from is not this file's business: the tests take a list of sampled
// directions (or points) together with the number of draws that produced none, and a pdf to
// test them against. The host tests fill the list with draw_directions(); a GPU test fills it
// from a compute shader's output buffer and calls the same test_directions().
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace tp::test::chi2 {

// At least 10^6 samples per test, so that a density error of a few percent in a cell is seen.
constexpr uint64_t kSamples = 1000000;
// Pearson's statistic is close to chi-square only when every cell expects >= 5 samples
// (Cochran's rule, which pbrt-v4 and Mitsuba 3 both use); smaller cells are pooled.
constexpr double kMinExpected = 5.0;

struct Result {
    double statistic = 0.0; // Pearson's X^2 = sum (observed - expected)^2 / expected
    int dof = 0;            // cells after pooling, minus 1 (no parameter is estimated)
    double p_value = 0.0;   // P(X^2 >= statistic) when the samples follow the pdf
    size_t cells = 0;       // cells tested, the one for failed draws included
    size_t pooled = 0;      // cells merged into the pool
    double mass = 0.0;      // the pdf integrated over the whole domain
    std::string error;      // set when the samples are rejected without a p-value

    // Accepted at significance level alpha.
    bool accepted(double alpha) const { return error.empty() && p_value >= alpha; }
    std::string summary() const;
};

// Per-test level for a family of m tests whose overall false-rejection rate is alpha
// (Sidak 1967): 1 - (1 - alpha)^(1/m).
double sidak_alpha(double alpha, int tests);

// Pearson's test of observed against expected counts. Cells are sorted by expected count and
// those below min_expected pooled until the pool reaches it (pbrt-v4, ChiSquareTest). A cell
// that expects exactly 0 but received more than 1e-5 of the samples rejects outright: the
// sampler produces values that the pdf says are impossible.
Result pearson(const std::vector<double>& observed, const std::vector<double>& expected,
               double min_expected = kMinExpected);

// Categorical frequencies: counts[i] draws of category i, whose probability is probs[i].
Result test_discrete(const std::vector<uint64_t>& counts, const std::vector<double>& probs);

// Two-sided exact binomial test: the probability, when each trial succeeds with probability
// p, of a success count at most as likely as `successes` (the "minlike" rule of R's
// binom.test), from Boost's binomial distribution.
double binomial_p_value(uint64_t successes, uint64_t trials, double p);

// ---- quadrature ---------------------------------------------------------------------------
using Function2D = std::function<double(double x, double y)>;

// Integral of f over [x0, x1] x [y0, y1]: nested adaptive 15-point Gauss-Kronrod (Boost), the
// inner integral over y evaluated at every node of the outer one over x. A panel is bisected
// while its Gauss-Kronrod error estimate |K15 - G7| exceeds rel_tol times the whole interval's
// value (Boost's rule), to at most 10 levels. The default 1e-3 sits above the rounding noise of
// pdfs evaluated in float (a Phong lobe of exponent n carries a relative noise of ~n * 3e-8,
// 3e-4 at n = 10^4, from rounding cos(alpha)), which a tighter tolerance would chase to the
// last level in every cell. The estimate bounds the 7-point Gauss rule's error; the 15-point
// Kronrod value returned is far more accurate on smooth panels, and a jump of f along a curve
// (a pdf cut off at the horizon) keeps being bisected and is located to 2^-10 of the cell. The
// unit tests measure the accuracy reached against closed forms (pdf_normalization_test.cpp).
double integrate_rect(const Function2D& f, double x0, double x1, double y0, double y1,
                      double rel_tol = 1e-3);

// A grid over a rectangle: cell (i, j) is [x_edges[i], x_edges[i+1]) x [y_edges[j],
// y_edges[j+1]), stored at index i * (ny) + j.
struct Grid {
    std::vector<double> x_edges, y_edges;

    static Grid uniform(double x0, double x1, size_t nx, double y0, double y1, size_t ny);
    size_t nx() const { return x_edges.size() - 1; }
    size_t ny() const { return y_edges.size() - 1; }
    size_t size() const { return nx() * ny(); }
    // The cell holding (x, y); the upper edges belong to the last cells; size() when outside.
    size_t cell(double x, double y) const;
    // f integrated over every cell.
    std::vector<double> integrate(const Function2D& f) const;
};

// ---- points in a rectangle ----------------------------------------------------------------
struct PointSamples {
    std::vector<glm::dvec2> points;
    uint64_t failed = 0; // draws that produced no point
};

Result test_points(const Grid& grid, const PointSamples& samples, const Function2D& pdf);

// ---- directions ---------------------------------------------------------------------------
// A chart of the unit sphere around `axis`: the polar angle theta in [0, pi] from the axis and
// the azimuth phi in [0, 2 pi) in the frame (t, b, axis). A solid-angle pdf is integrated as
// pdf sin(theta) dtheta dphi; in these coordinates the integrand stays smooth where the pdf has
// a 1 / sin(theta) factor (an environment map's, at its poles) and vanishes at the axis.
struct SphereChart {
    glm::dvec3 axis, t, b;
    Grid grid; // x: theta, y: phi

    // Any cells: theta_edges from 0 to pi, phi_edges from 0 to 2 pi, phi measured from t
    // towards b; (t, b, axis) orthonormal, of either handedness. For pdfs that are piecewise
    // smooth on a known partition of the sphere (an environment map's pixels), edges on the
    // partition keep every cell smooth.
    SphereChart(const glm::dvec3& axis, const glm::dvec3& t, const glm::dvec3& b,
                std::vector<double> theta_edges, std::vector<double> phi_edges);

    // Rows uniform in cos(theta) (equal solid angles): for pdfs that vary slowly.
    static SphereChart uniform(const glm::dvec3& axis, size_t rows, size_t cols);
    // Rows logarithmic in s = 1 - cos(theta), s_k = s0 ((1 + 2 / s0)^(k / rows) - 1): cells of
    // width ~s0 at the axis growing geometrically to the antipode, so that a lobe of width s0
    // about the axis is resolved (a Phong lobe cos^n has 1 - cos(alpha) ~ 1 / n) while the
    // grid still covers the whole sphere. The row edge nearest s = 1 is moved onto it, so that
    // a pdf confined to the hemisphere about the axis has its edge on cell boundaries.
    static SphereChart lobe(const glm::dvec3& axis, double s0, size_t rows, size_t cols);

    glm::dvec2 coords(const glm::dvec3& w) const; // unit w -> (theta, phi)
    glm::dvec3 direction(double theta, double phi) const;
};

using DirectionPdf = std::function<double(const glm::dvec3& w)>;

struct DirectionSamples {
    std::vector<glm::dvec3> directions; // unit, normalised in double precision
    uint64_t failed = 0;                // draws that produced no direction

    // Adds a sampled direction (any length > 0) as its exact direction in double precision.
    void add(const glm::vec3& w);
};

Result test_directions(const SphereChart& chart, const DirectionSamples& samples,
                       const DirectionPdf& pdf);

// Integral of f over the sphere with the chart's cells as quadrature panels.
double integrate_sphere(const SphereChart& chart, const DirectionPdf& f);

// ---- drawing samples on the host ----------------------------------------------------------
// Uniform numbers with the renderer's resolution (24-bit floats in [0, 1), rng.h) from an
// independent generator, so that a test of a sampler does not rest on the renderer's hash.
class Uniform {
  public:
    explicit Uniform(uint64_t seed) : gen_(seed) {}
    float next() { return float(uint32_t(gen_()) >> 8) * (1.0f / 16777216.0f); }
    // A whole 32-bit word, as rng_get_bits gives the alias-table slot choice.
    uint32_t bits() { return uint32_t(gen_()); }
    glm::vec4 next4() {
        const float a = next(), b = next(), c = next();
        return glm::vec4(a, b, c, next());
    }

  private:
    std::mt19937_64 gen_;
};

// A sampler maps four uniform numbers (as many as any sampler of the renderer consumes: a
// discrete choice, its alias coin and a 2D point) to a direction, or to nothing (a failed draw).
using DirectionSampler = std::function<std::optional<glm::vec3>(const glm::vec4& u)>;
using PointSampler = std::function<std::optional<glm::vec2>(const glm::vec4& u)>;

DirectionSamples draw_directions(const DirectionSampler& sampler, uint64_t n, uint64_t seed);
PointSamples draw_points(const PointSampler& sampler, uint64_t n, uint64_t seed);

} // namespace tp::test::chi2
