#include "support/chi2.h"

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tp::test::chi2 {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr unsigned kMaxLevels = 7;
// Absolute tolerance per cell, in units of probability: 10^-12 is 10^-6 samples of 10^6, so
// the tails of narrow lobes, where a float pdf underflows into denormals, are not refined.
constexpr double kAbsTol = 1e-12;
// Samples tolerated in a cell where the pdf integrates to 0, as a fraction of all samples
// (pbrt-v4's ChiSquareTest uses the same 1e-5): float rounding puts the odd sample a few ulps
// across an edge where the pdf drops to 0 (a triangle's edge, the horizon), and a sliver of a
// cell that the cubature's nodes all miss integrates to 0. Such samples stay in the statistic,
// in the pool; more of them reject outright.
constexpr double kZeroCellLeniency = 1e-5;

// Orthonormal basis around a unit vector (Duff et al., JCGT 6(1), 2017), in double precision
// and written here rather than taken from shared/math.h, so the test frame is independent of
// the code under test.
void basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double s = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (s + n.z);
    const double c = n.x * n.y * a;
    t = glm::dvec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = glm::dvec3(c, s + n.y * n.y * a, -n.y);
}

// Rows given as s = 1 - cos(theta), columns uniform in phi.
SphereChart chart_with_rows(const glm::dvec3& axis, const std::vector<double>& s_edges,
                            size_t cols) {
    std::vector<double> theta;
    for (double s : s_edges) theta.push_back(2.0 * std::asin(std::sqrt(std::min(1.0, 0.5 * s))));
    const glm::dvec3 n = glm::normalize(axis);
    glm::dvec3 t, b;
    basis(n, t, b);
    std::vector<double> phi(cols + 1);
    for (size_t j = 0; j <= cols; ++j) phi[j] = 2.0 * kPi * double(j) / double(cols);
    return SphereChart(n, t, b, theta, phi);
}

} // namespace

std::string Result::summary() const {
    if (!error.empty()) return "rejected: " + error;
    return fmt::format("X^2 = {:.1f}, dof = {}, p = {:.4g} ({} cells, {} pooled, pdf mass {:.9f})",
                       statistic, dof, p_value, cells, pooled, mass);
}

double sidak_alpha(double alpha, int tests) {
    return 1.0 - std::pow(1.0 - alpha, 1.0 / double(tests));
}

Result pearson(const std::vector<double>& observed, const std::vector<double>& expected,
               double min_expected) {
    Result r;
    r.cells = observed.size();
    const double n = std::accumulate(observed.begin(), observed.end(), 0.0);
    std::vector<size_t> order(observed.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double pool_observed = 0.0, pool_expected = 0.0;
    for (size_t i : order) {
        const double o = observed[i], e = expected[i];
        if (!(e >= 0.0) || !std::isfinite(e)) {
            r.error = fmt::format("cell {} has an invalid expected count {}", i, e);
            return r;
        }
        if (e == 0.0 && o > kZeroCellLeniency * n) {
            r.error = fmt::format("{} samples in cell {}, where the pdf is 0", o, i);
            return r;
        }
        if (e == 0.0 && o == 0.0) continue; // nothing expected, nothing seen
        // Sorted by expected count, the small cells (the empty ones first) go into the pool,
        // and the pool takes further cells until it expects min_expected.
        if (e < min_expected || (r.pooled > 0 && pool_expected < min_expected)) {
            pool_observed += o;
            pool_expected += e;
            ++r.pooled;
            continue;
        }
        r.statistic += (o - e) * (o - e) / e;
        ++r.dof;
    }
    if (pool_expected > 0.0) {
        r.statistic +=
            (pool_observed - pool_expected) * (pool_observed - pool_expected) / pool_expected;
        ++r.dof;
    }
    r.dof -= 1;
    if (r.dof < 1) {
        r.error = "fewer than two cells to compare";
        return r;
    }
    const boost::math::chi_squared dist(r.dof);
    r.p_value = boost::math::cdf(boost::math::complement(dist, r.statistic));
    return r;
}

Result test_discrete(const std::vector<uint64_t>& counts, const std::vector<double>& probs) {
    const double n = double(std::accumulate(counts.begin(), counts.end(), uint64_t(0)));
    std::vector<double> observed(counts.begin(), counts.end()), expected(probs.size());
    for (size_t i = 0; i < probs.size(); ++i) expected[i] = n * probs[i];
    Result r = pearson(observed, expected);
    r.mass = std::accumulate(probs.begin(), probs.end(), 0.0);
    return r;
}

double binomial_p_value(uint64_t successes, uint64_t trials, double p) {
    const boost::math::binomial dist(double(trials), p);
    const double k = double(successes);
    const double lower = boost::math::cdf(dist, k);
    const double upper = k == 0.0 ? 1.0 : boost::math::cdf(boost::math::complement(dist, k - 1.0));
    return std::min(1.0, 2.0 * std::min(lower, upper));
}

namespace {

// 5 x 5 tensor Gauss-Legendre rule on a rectangle: exact for polynomials of degree 9 in each
// variable.
struct GaussLegendre5 {
    double x[5], w[5];
    GaussLegendre5() {
        using G = boost::math::quadrature::gauss<double, 5>;
        // Boost stores the non-negative half of the symmetric nodes, the centre first.
        for (int i = 0; i < 3; ++i) {
            x[2 + i] = G::abscissa()[size_t(i)];
            x[2 - i] = -G::abscissa()[size_t(i)];
            w[2 + i] = w[2 - i] = G::weights()[size_t(i)];
        }
    }
    double operator()(const Function2D& f, double x0, double x1, double y0, double y1) const {
        const double cx = 0.5 * (x0 + x1), hx = 0.5 * (x1 - x0);
        const double cy = 0.5 * (y0 + y1), hy = 0.5 * (y1 - y0);
        double sum = 0.0;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j) sum += w[i] * w[j] * f(cx + hx * x[i], cy + hy * x[j]);
        return sum * hx * hy;
    }
};

// Adaptive cubature: the panel's estimate is compared with the sum over its four quadrants,
// which is accepted when they agree to rel_tol of the value or to the panel's share of the
// absolute tolerance (a quarter per level, so the accepted panels' errors add up to at most
// abs_tol), else every quadrant is refined in turn. A jump of f along a curve keeps the panels
// it crosses refining to the last level, where they cover 2^-levels of the cell's area.
double adaptive(const GaussLegendre5& rule, const Function2D& f, double x0, double x1, double y0,
                double y1, double whole, double rel_tol, double abs_tol, unsigned levels) {
    const double mx = 0.5 * (x0 + x1), my = 0.5 * (y0 + y1);
    const double q[4] = {rule(f, x0, mx, y0, my), rule(f, mx, x1, y0, my), rule(f, x0, mx, my, y1),
                         rule(f, mx, x1, my, y1)};
    const double sum = q[0] + q[1] + q[2] + q[3];
    if (levels == 0 || std::abs(sum - whole) <= std::max(rel_tol * std::abs(sum), abs_tol))
        return sum;
    const double t = 0.25 * abs_tol;
    return adaptive(rule, f, x0, mx, y0, my, q[0], rel_tol, t, levels - 1) +
           adaptive(rule, f, mx, x1, y0, my, q[1], rel_tol, t, levels - 1) +
           adaptive(rule, f, x0, mx, my, y1, q[2], rel_tol, t, levels - 1) +
           adaptive(rule, f, mx, x1, my, y1, q[3], rel_tol, t, levels - 1);
}

} // namespace

double integrate_rect(const Function2D& f, double x0, double x1, double y0, double y1,
                      double rel_tol) {
    static const GaussLegendre5 rule;
    return adaptive(rule, f, x0, x1, y0, y1, rule(f, x0, x1, y0, y1), rel_tol, kAbsTol, kMaxLevels);
}

Grid Grid::uniform(double x0, double x1, size_t nx, double y0, double y1, size_t ny) {
    Grid g;
    for (size_t i = 0; i <= nx; ++i) g.x_edges.push_back(x0 + (x1 - x0) * double(i) / double(nx));
    for (size_t j = 0; j <= ny; ++j) g.y_edges.push_back(y0 + (y1 - y0) * double(j) / double(ny));
    return g;
}

size_t Grid::cell(double x, double y) const {
    const auto index = [](const std::vector<double>& edges, double v) -> size_t {
        if (!(v >= edges.front() && v <= edges.back())) return size_t(-1);
        const size_t i = size_t(std::upper_bound(edges.begin(), edges.end(), v) - edges.begin());
        return std::min(i, edges.size() - 1) - 1;
    };
    const size_t i = index(x_edges, x), j = index(y_edges, y);
    if (i == size_t(-1) || j == size_t(-1)) return size();
    return i * ny() + j;
}

std::vector<double> Grid::integrate(const Function2D& f) const {
    std::vector<double> out(size());
    for (size_t i = 0; i < nx(); ++i)
        for (size_t j = 0; j < ny(); ++j)
            out[i * ny() + j] =
                integrate_rect(f, x_edges[i], x_edges[i + 1], y_edges[j], y_edges[j + 1]);
    return out;
}

namespace {

// Counts, expected counts and the test, shared by points and directions. The cell after the
// grid's last holds the failed draws, which are expected at the rate of the pdf's missing mass
// 1 - mass: a sampler that gives up exactly where its pdf has no mass passes.
Result test_binned(const std::vector<size_t>& cells, uint64_t failed, uint64_t invalid,
                   const std::vector<double>& cell_mass, size_t outside_cell) {
    Result r;
    r.mass = std::accumulate(cell_mass.begin(), cell_mass.end(), 0.0);
    if (invalid > 0) {
        r.error = fmt::format("{} sample(s) are NaN, infinite or of zero length", invalid);
        return r;
    }
    const double n = double(cells.size() + failed);
    std::vector<double> observed(cell_mass.size() + 1, 0.0), expected(cell_mass.size() + 1);
    for (size_t c : cells) {
        if (c == outside_cell) {
            r.error = "a sample lies outside the grid's domain";
            return r;
        }
        observed[c] += 1.0;
    }
    observed.back() = double(failed);
    for (size_t i = 0; i < cell_mass.size(); ++i) expected[i] = n * cell_mass[i];
    expected.back() = n * std::max(0.0, 1.0 - r.mass);
    const double mass = r.mass;
    r = pearson(observed, expected);
    r.mass = mass;
    return r;
}

} // namespace

Result test_points(const Grid& grid, const PointSamples& samples, const Function2D& pdf) {
    std::vector<size_t> cells;
    cells.reserve(samples.points.size());
    uint64_t invalid = 0;
    for (const glm::dvec2& p : samples.points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            ++invalid;
            continue;
        }
        cells.push_back(grid.cell(p.x, p.y));
    }
    return test_binned(cells, samples.failed, invalid, grid.integrate(pdf), grid.size());
}

SphereChart::SphereChart(const glm::dvec3& axis_, const glm::dvec3& t_, const glm::dvec3& b_,
                         std::vector<double> theta_edges, std::vector<double> phi_edges)
    : axis(axis_), t(t_), b(b_) {
    grid.x_edges = std::move(theta_edges);
    grid.y_edges = std::move(phi_edges);
}

SphereChart SphereChart::uniform(const glm::dvec3& axis, size_t rows, size_t cols) {
    std::vector<double> s(rows + 1);
    for (size_t i = 0; i <= rows; ++i) s[i] = 2.0 * double(i) / double(rows);
    return chart_with_rows(axis, s, cols);
}

SphereChart SphereChart::lobe(const glm::dvec3& axis, double s0, size_t rows, size_t cols) {
    std::vector<double> s(rows + 1);
    const double ratio = 1.0 + 2.0 / s0;
    for (size_t i = 0; i < rows; ++i) s[i] = s0 * (std::pow(ratio, double(i) / double(rows)) - 1.0);
    s[rows] = 2.0;
    // The edge nearest the plane perpendicular to the axis moves onto it.
    *std::min_element(s.begin() + 1, s.end() - 1, [](double a, double b) {
        return std::abs(a - 1.0) < std::abs(b - 1.0);
    }) = 1.0;
    return chart_with_rows(axis, s, cols);
}

glm::dvec2 SphereChart::coords(const glm::dvec3& w) const {
    // theta = 2 asin(|w - axis| / 2) for unit vectors: no cancellation near the axis, where
    // the narrow lobes are, unlike acos(dot(w, axis)).
    const double theta = 2.0 * std::asin(std::min(1.0, 0.5 * glm::length(w - axis)));
    double phi = std::atan2(glm::dot(w, b), glm::dot(w, t));
    if (phi < 0.0) phi += 2.0 * kPi;
    return glm::dvec2(theta, std::min(phi, 2.0 * kPi));
}

glm::dvec3 SphereChart::direction(double theta, double phi) const {
    const double st = std::sin(theta);
    return st * std::cos(phi) * t + st * std::sin(phi) * b + std::cos(theta) * axis;
}

void DirectionSamples::add(const glm::vec3& w) {
    const glm::dvec3 d(w);
    const double len = glm::length(d);
    directions.push_back(len > 0.0 && std::isfinite(len) ? d / len : glm::dvec3(NAN));
}

namespace {

// The solid-angle integrand in the chart's coordinates: d omega = sin(theta) dtheta dphi.
std::vector<double> integrate_cells(const SphereChart& chart, const DirectionPdf& f) {
    return chart.grid.integrate(
        [&](double theta, double phi) { return f(chart.direction(theta, phi)) * std::sin(theta); });
}

} // namespace

double integrate_sphere(const SphereChart& chart, const DirectionPdf& f) {
    const std::vector<double> cells = integrate_cells(chart, f);
    return std::accumulate(cells.begin(), cells.end(), 0.0);
}

Result test_directions(const SphereChart& chart, const DirectionSamples& samples,
                       const DirectionPdf& pdf) {
    std::vector<size_t> cells;
    cells.reserve(samples.directions.size());
    uint64_t invalid = 0;
    for (const glm::dvec3& w : samples.directions) {
        if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) {
            ++invalid;
            continue;
        }
        const glm::dvec2 c = chart.coords(w);
        cells.push_back(chart.grid.cell(c.x, c.y));
    }
    return test_binned(cells, samples.failed, invalid, integrate_cells(chart, pdf),
                       chart.grid.size());
}

DirectionSamples draw_directions(const DirectionSampler& sampler, uint64_t n, uint64_t seed) {
    Uniform u(seed);
    DirectionSamples s;
    s.directions.reserve(n);
    for (uint64_t i = 0; i < n; ++i) {
        const std::optional<glm::vec3> w = sampler(u.next4());
        if (w)
            s.add(*w);
        else
            ++s.failed;
    }
    return s;
}

PointSamples draw_points(const PointSampler& sampler, uint64_t n, uint64_t seed) {
    Uniform u(seed);
    PointSamples s;
    s.points.reserve(n);
    for (uint64_t i = 0; i < n; ++i) {
        const std::optional<glm::vec2> p = sampler(u.next4());
        if (p)
            s.points.push_back(glm::dvec2(*p));
        else
            ++s.failed;
    }
    return s;
}

} // namespace tp::test::chi2
