#include "forces/ForceModels.H"

#include <algorithm>

namespace suspension
{

const std::vector<std::string>& contributionNames()
{
    static const std::vector<std::string> names = []
    {
        std::vector<std::string> n;
        auto add = [&](auto tag)
        {
            const std::string c = decltype(tag)::type::contribution;
            if (std::find(n.begin(), n.end(), c) == n.end())
            {
                n.push_back(c);
            }
        };
        forEachParticleModelType(add);
        forEachPairModelType(add);
        return n;
    }();
    return names;
}


const std::vector<bool>& hydrodynamicContributions()
{
    static const std::vector<bool> hydrodynamic = []
    {
        std::vector<bool> h(contributionNames().size(), false);
        auto mark = [&](auto tag)
        {
            using M = typename decltype(tag)::type;
            h[contributionIndex(M::contribution)] = M::hydrodynamic;
        };
        forEachParticleModelType(mark);
        forEachPairModelType(mark);
        return h;
    }();
    return hydrodynamic;
}


int contributionIndex(const char* name)
{
    const std::vector<std::string>& names = contributionNames();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
    {
        throw std::logic_error(std::string("unknown stress contribution ") + name);
    }
    return static_cast<int>(it - names.begin());
}


unsigned ForceModels::activeMask() const
{
    unsigned mask = 0;
    unsigned bit = 1;
    std::apply
    (
        [&](const auto&... m) { ((mask |= m ? bit : 0, bit <<= 1), ...); },
        pair_
    );
    return mask;
}


double ForceModels::interactionGap() const
{
    double gap = 0;
    forEach([&](const auto& m) { gap = std::max(gap, m.gap()); });
    return gap;
}


std::string ForceModels::summary() const
{
    std::string s;
    auto add = [&](const auto& m)
    {
        s += s.empty() ? "" : " ";
        s += std::decay_t<decltype(m)>::typeName;
    };
    forEachParticleModel(add);
    forEach(add);
    return s;
}

} // namespace suspension
