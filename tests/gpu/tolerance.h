// How far a GPU result may be from the C++ result of the same shared function, and the
// bookkeeping of a comparison.
//
// Where GPU and CPU can differ (Vulkan 1.2 specification, "Precision and Operation of SPIR-V
// Instructions"; the host computes in IEEE float with round-to-nearest, -ffp-contract=off):
//  - OpFAdd, OpFSub, OpFMul, conversions, min/max/abs/floor, comparisons: correctly rounded,
//    so bit-identical on both sides for identical inputs ...
//  - ... except that SPIR-V allows a*b + c to be contracted into one fma (no NoContraction
//    decoration), which changes the result by at most u |a b| (u = 2^-24, unit roundoff).
//  - OpFDiv: 2.5 ulp (the host: 0.5 ulp), so quotients may differ by 3 ulp.
//  - inversesqrt: 2 ulp; sqrt: inherited from 1/inversesqrt, so 2 + 2.5 ulp (+ 0.5 on the host).
//  - exp, exp2: 3 + 2|x| ulp. log, log2: 3 ulp outside [0.5, 2], absolute 2^-21 inside.
//    pow: inherited from exp2(y log2 x).
//  - sin, cos: absolute 2^-11 (we apply it beyond [-pi, pi] too: the shared code passes angles
//    in [0, 2 pi) whose range reduction is exact to float rounding). tan: inherited sin/cos.
//  - atan, atan2: 4096 ulp; acos: inherited from atan2(sqrt(1 - x^2), x).
//  - denormals may be flushed to zero: results below 2^-126 compare with that absolute slack.
// A branch on a float comparison (a sample below the horizon, a lobe choice) takes the other
// side when its operands lie within those errors of each other; functions with such branches
// may disagree on a small fraction of inputs (Case::outliers).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include <fmt/format.h>
#include <glm/glm.hpp>

namespace tp::test {

constexpr double kU = 0x1p-24;             // unit roundoff of float
constexpr double kUlp = 0x1p-23;           // ulp of [1, 2): n ulp ~ relative n * kUlp
constexpr double kDivRel = 3.0 * kUlp;     // GPU 2.5 ulp + host 0.5 ulp
constexpr double kSqrtRel = 5.0 * kUlp;    // 2 + 2.5 ulp (GPU) + 0.5 ulp (host)
constexpr double kInvSqrtRel = 2.5 * kUlp; // 2 ulp + host rounding
constexpr double kSinCosAbs = 0x1p-11;     // sin, cos
constexpr double kAtanRel = 4096.0 * kUlp; // atan, atan2, and acos through it
constexpr double kLogAbsNearOne = 0x1p-21; // log, log2 on [0.5, 2]
constexpr double kLogRel = 3.0 * kUlp;     // log, log2 elsewhere
constexpr double kFlushAbs = 0x1p-125;     // twice the smallest normal float
inline double exp_rel(double x) {
    return (3.0 + 2.0 * std::abs(x)) * kUlp;
}
// Absolute error bounds of log(x) and log2(x) results.
inline double log_abs(double x) {
    return (x >= 0.5 && x <= 2.0) ? kLogAbsNearOne : kLogRel * std::abs(std::log(x));
}
inline double log2_abs(double x) {
    return (x >= 0.5 && x <= 2.0) ? kLogAbsNearOne : kLogRel * std::abs(std::log2(x));
}

// The comparison of one input's results: every component is checked, the first failure is kept
// for the message, and the largest |gpu - cpu| / tolerance is tracked.
class Checker {
  public:
    // |gpu - cpu| <= abs + rel |cpu|, both NaN, or both the same infinity.
    void close(const char* what, double gpu, double cpu, double abs, double rel) {
        if (std::isnan(gpu) && std::isnan(cpu)) return;
        if (std::isinf(gpu) || std::isinf(cpu)) {
            if (gpu != cpu) fail(what, gpu, cpu, 0.0);
            return;
        }
        const double tol = abs + rel * std::abs(cpu) + kFlushAbs;
        const double err = std::abs(gpu - cpu);
        worst_ = std::max(worst_, err / tol);
        if (!(err <= tol)) fail(what, gpu, cpu, tol);
    }
    void close3(const char* what, glm::vec3 gpu, glm::vec3 cpu, double abs, double rel) {
        for (int i = 0; i < 3; ++i) close(what, gpu[i], cpu[i], abs, rel);
    }
    void exact(const char* what, uint32_t gpu, uint32_t cpu) {
        if (gpu != cpu) fail(what, gpu, cpu, 0.0);
    }
    // Bitwise equality of floats (NaNs of any payload equal).
    void same(const char* what, float gpu, float cpu) {
        uint32_t g, c;
        std::memcpy(&g, &gpu, 4);
        std::memcpy(&c, &cpu, 4);
        if (g != c && !(std::isnan(gpu) && std::isnan(cpu))) fail(what, gpu, cpu, 0.0);
    }
    void same3(const char* what, glm::vec3 gpu, glm::vec3 cpu) {
        for (int i = 0; i < 3; ++i) same(what, gpu[i], cpu[i]);
    }

    bool failed() const { return failed_; }
    const std::string& message() const { return message_; }
    // The largest |gpu - cpu| / tolerance of the current input.
    double input_worst() const { return worst_; }
    void reset_input() {
        failed_ = false;
        message_.clear();
        worst_ = 0.0;
    }

  private:
    void fail(const char* what, double gpu, double cpu, double tol) {
        if (!failed_)
            message_ = fmt::format("{}: gpu {:.9g} cpu {:.9g} tol {:.3g}", what, gpu, cpu, tol);
        failed_ = true;
    }
    bool failed_ = false;
    std::string message_;
    double worst_ = 0.0;
};

} // namespace tp::test
