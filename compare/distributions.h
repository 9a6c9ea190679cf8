// The few distribution functions compare needs, all from Boost.Math.
#pragma once

namespace tp {

// P(|T| >= |z|) for Student's t with `dof` degrees of freedom (normal when dof is infinite).
double two_sided_p(double z, double dof);

// The standard-normal quantile with the same upper tail as t = z under Student's t(dof), sign
// kept, so that statistics of different dof can be pooled as N(0,1) variables.
double equivalent_normal(double z, double dof);

// P(X >= x) for X ~ chi-square with k degrees of freedom, and the x at which it is p.
double chi2_upper(double x, double k);
double chi2_upper_quantile(double p, double k);

// P(Z >= z) and its inverse for Z ~ N(0,1).
double normal_upper(double z);
double normal_upper_quantile(double p);

} // namespace tp
