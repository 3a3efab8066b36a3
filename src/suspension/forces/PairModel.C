#include "forces/PairModel.H"

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

} // namespace suspension
