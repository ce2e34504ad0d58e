"""Welch's two-sample t-test in pure Python (no SciPy), for the reproduction tables.

The TEXPLORE-VANIR paper marks its comparisons with p-values (p < 0.025, p < 0.001); the tables
of plot_results.py and reproduce_nao.py give, per measured column, the two-sided p of Welch's
unequal-variance t-test of an agent's per-trial values against the reference agent's:

  t  = (m1 - m2) / sqrt(s1^2/n1 + s2^2/n2)
  df = (s1^2/n1 + s2^2/n2)^2 / ((s1^2/n1)^2/(n1-1) + (s2^2/n2)^2/(n2-1))   (Welch-Satterthwaite)
  p  = P(|T_df| >= |t|) = I_{df/(df+t^2)}(df/2, 1/2)

with s^2 the unbiased sample variances and I_x(a, b) the regularized incomplete beta function,
evaluated by its continued fraction (Numerical Recipes, 2nd ed., section 6.4, `betai`/`betacf`).
Only the standard library is used; plot_results.py imports this file from its own folder.
"""
import math

__all__ = ["betai", "student_t_cdf", "student_t_two_sided_p", "welch_t_test", "format_p",
           "p_value_note"]

_EPS = 1e-15
_TINY = 1e-300
_MAXIT = 500


def _lentz_step(aa, c, d):
    """One modified-Lentz update of a continued fraction's numerator and denominator terms."""
    d = 1.0 + aa * d
    if abs(d) < _TINY:
        d = _TINY
    c = 1.0 + aa / c
    if abs(c) < _TINY:
        c = _TINY
    return c, 1.0 / d


def _betacf(a, b, x):
    """Continued fraction of the incomplete beta function (modified Lentz, NR's betacf)."""
    qab, qap, qam = a + b, a + 1.0, a - 1.0
    c = 1.0
    d = 1.0 - qab * x / qap
    if abs(d) < _TINY:
        d = _TINY
    d = 1.0 / d
    h = d
    for m in range(1, _MAXIT + 1):
        m2 = 2 * m
        # Even then odd step of the continued fraction (Lentz's method).
        c, d = _lentz_step(m * (b - m) * x / ((qam + m2) * (a + m2)), c, d)
        h *= d * c
        c, d = _lentz_step(-(a + m) * (qab + m) * x / ((a + m2) * (qap + m2)), c, d)
        delta = d * c
        h *= delta
        if abs(delta - 1.0) < _EPS:
            return h
    raise ArithmeticError("stats.betai(): continued fraction did not converge "
                          "(a=%g, b=%g, x=%g)" % (a, b, x))


def betai(a, b, x):
    """The regularized incomplete beta function I_x(a, b), for a, b > 0 and 0 <= x <= 1."""
    if a <= 0 or b <= 0:
        raise ValueError("stats.betai(): a and b must be positive (a=%g, b=%g)" % (a, b))
    if not 0.0 <= x <= 1.0:
        raise ValueError("stats.betai(): x must be in [0, 1] (x=%g)" % x)
    if x == 0.0 or x == 1.0:
        return x
    ln_front = (math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x)
                + b * math.log1p(-x))
    front = math.exp(ln_front)
    # The continued fraction converges fast for x < (a+1)/(a+b+2); use the symmetry
    # I_x(a, b) = 1 - I_{1-x}(b, a) on the other side.
    if x < (a + 1.0) / (a + b + 2.0):
        return front * _betacf(a, b, x) / a
    return 1.0 - front * _betacf(b, a, 1.0 - x) / b


def student_t_two_sided_p(t, df):
    """P(|T| >= |t|) for Student's t with df > 0 degrees of freedom (df need not be whole)."""
    if df <= 0:
        raise ValueError("stats.student_t_two_sided_p(): df must be positive (df=%g)" % df)
    if math.isnan(t):
        return float("nan")
    if math.isinf(t):
        return 0.0
    return min(1.0, betai(0.5 * df, 0.5, df / (df + t * t)))


def student_t_cdf(t, df):
    """P(T <= t) for Student's t with df > 0 degrees of freedom."""
    tail = 0.5 * student_t_two_sided_p(t, df)
    return 1.0 - tail if t > 0 else tail


def _finite(values):
    return [float(v) for v in values if not math.isnan(float(v))]


def _mean_var(v):
    m = math.fsum(v) / len(v)
    return m, math.fsum((x - m) ** 2 for x in v) / (len(v) - 1)


def welch_t_test(a, b):
    """Two-sided Welch t-test of samples a and b: (t, df, p).

    NaN values are ignored (a trial without that measurement). When either sample has fewer
    than 2 values, or both have zero variance, the test is undefined and all three are NaN.
    """
    a, b = _finite(a), _finite(b)
    if len(a) < 2 or len(b) < 2:
        return float("nan"), float("nan"), float("nan")
    m1, v1 = _mean_var(a)
    m2, v2 = _mean_var(b)
    q1, q2 = v1 / len(a), v2 / len(b)
    se2 = q1 + q2
    if se2 <= 0.0:
        return float("nan"), float("nan"), float("nan")
    t = (m1 - m2) / math.sqrt(se2)
    df = se2 * se2 / (q1 * q1 / (len(a) - 1) + q2 * q2 / (len(b) - 1))
    return t, df, student_t_two_sided_p(t, df)


def format_p(p):
    """A p-value for a table: 'n/a' when undefined, '< 0.001' when tiny, else 3 decimals."""
    if p is None or math.isnan(p):
        return "n/a"
    if p < 0.001:
        return "< 0.001"
    return "%.3f" % p


def p_value_note(reference):
    """The line under a table that says what its p columns are."""
    return ("p: two-sided Welch t-test of each agent's per-trial values against %s (the row "
            "marked ref); n/a when either has fewer than 2 trials or both have zero variance."
            % reference)
