#include "stress/Oscillation.H"
#include "core/Vector.H"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace suspension
{

namespace
{
    using Complex = std::complex<double>;

    //- (2/T) int_a^b f(t) exp(-i m omega t) dt for m = 1 and 3 of the
    //  piecewise-linear interpolant of the samples, trapezoidal rule
    struct Coefficients
    {
        Complex c1;
        Complex c3;
        double scale;   // largest |f| of the cycle
    };

    Coefficients coefficients
    (
        const std::vector<double>& t,
        const std::vector<double>& f,
        double a,
        double b,
        double omega,
        bool detrend = false
    )
    {
        // The samples inside (a, b) and the interpolated ends
        auto at = [&](double s)
        {
            std::size_t k = 1;
            while (k + 1 < t.size() && t[k] < s)
            {
                ++k;
            }
            const double h = t[k] - t[k - 1];
            const double w = h > 0 ? (s - t[k - 1])/h : 1;
            return (1 - w)*f[k - 1] + w*f[k];
        };
        std::vector<double> ts{a};
        std::vector<double> fs{at(a)};
        for (std::size_t k = 0; k < t.size(); ++k)
        {
            if (t[k] > a && t[k] < b)
            {
                ts.push_back(t[k]);
                fs.push_back(f[k]);
            }
        }
        ts.push_back(b);
        fs.push_back(at(b));

        // A drift over the cycle (a mean rate) taken out: its line has a
        // first harmonic of its own
        if (detrend)
        {
            const double slope = (fs.back() - fs.front())/(b - a);
            for (std::size_t k = 0; k < ts.size(); ++k)
            {
                fs[k] -= slope*(ts[k] - a);
            }
        }

        Coefficients c{0, 0, 0};
        for (const double x : fs)
        {
            c.scale = std::max(c.scale, std::abs(x));
        }
        for (std::size_t k = 0; k + 1 < ts.size(); ++k)
        {
            const double h = ts[k + 1] - ts[k];
            for (const int m : {1, 3})
            {
                const Complex e0 = std::polar(1.0, -m*omega*ts[k]);
                const Complex e1 = std::polar(1.0, -m*omega*ts[k + 1]);
                const Complex s = 0.5*h*(fs[k]*e0 + fs[k + 1]*e1);
                (m == 1 ? c.c1 : c.c3) += s;
            }
        }
        const double scale = 2/(b - a);
        c.c1 *= scale;
        c.c3 *= scale;
        return c;
    }
}


Oscillation::Oscillation
(
    const std::vector<double>& t,
    const std::vector<double>& gamma,
    const std::vector<double>& sigma,
    double omega,
    std::size_t discard
)
:
    omega_(omega),
    discard_(discard)
{
    if (!(omega > 0) || gamma.size() != t.size() || sigma.size() != t.size())
    {
        throw std::invalid_argument
        (
            "Oscillation: need omega > 0 (got " + std::to_string(omega)
          + ") and as many strains and stresses as times"
        );
    }
    if (t.size() < 2)
    {
        return;
    }
    // Whole cycles within the samples, to the precision of their times
    const double T = 2*pi/omega;
    const double slack = 1e-5*std::max(T, std::abs(t.back()));
    for
    (
        double n = std::ceil((t.front() - slack)/T);
        (n + 1)*T <= t.back() + slack;
        ++n
    )
    {
        const Coefficients g =
            coefficients(t, gamma, n*T, (n + 1)*T, omega, true);
        const Coefficients s = coefficients(t, sigma, n*T, (n + 1)*T, omega);
        // A first harmonic of round-off size is none
        const bool strain = std::abs(g.c1) > 1e-9*g.scale;
        const bool stress = std::abs(s.c1) > 1e-9*s.scale;
        if (!strain || !stress)
        {
            throw std::invalid_argument
            (
                "Oscillation: no first harmonic of the "
              + std::string(strain ? "stress" : "strain")
              + " in the cycle from t = " + std::to_string(n*T)
              + " at omega = " + std::to_string(omega)
              + ": not an oscillation at that frequency"
            );
        }
        const Complex G = s.c1/g.c1;
        cycles_.push_back
        ({
            static_cast<std::size_t>(n), n*T, std::abs(g.c1), G.real(), G.imag(), G.imag()/omega,
            G.real()/omega, std::abs(s.c3)/std::abs(s.c1)
        });
    }
}


std::size_t Oscillation::nUsed() const
{
    std::size_t n = 0;
    for (const Cycle& c : cycles_)
    {
        n += used(c);
    }
    return n;
}


Oscillation::Estimate Oscillation::estimate(double Cycle::*quantity) const
{
    Estimate e;
    const std::size_t n = nUsed();
    if (n == 0)
    {
        return e;
    }
    for (const Cycle& c : cycles_)
    {
        e.mean += used(c) ? c.*quantity : 0;
    }
    e.mean /= n;
    if (n > 1)
    {
        double ss = 0;
        for (const Cycle& c : cycles_)
        {
            const double d = c.*quantity - e.mean;
            ss += used(c) ? d*d : 0;
        }
        e.error = std::sqrt(ss/(n - 1)/n);
    }
    return e;
}

} // namespace suspension
