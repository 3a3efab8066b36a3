#include "forces/PairModel.H"

#include <cmath>
#include <limits>

namespace suspension
{

ModelInput::Range ModelInput::Range::positive()
{
    return {0, std::numeric_limits<double>::infinity(), true, true};
}


ModelInput::Range ModelInput::Range::nonNegative()
{
    return {0, std::numeric_limits<double>::infinity(), false, true};
}


ModelInput::Range ModelInput::Range::open(double a, double b)
{
    return {a, b, true, true};
}


bool ModelInput::Range::contains(double v) const
{
    return std::isfinite(v)
        && (minOpen ? v > min : v >= min)
        && (maxOpen ? v < max : v <= max);
}

} // namespace suspension
