#include "forces/ForceModels.H"

#include <algorithm>

namespace suspension
{

const char* contributionName(int c)
{
    static const char* names[nContributions] =
        {"stokes", "lubrication", "contact", "repulsion", "attraction"};
    return names[c];
}


double ForceModels::interactionGap(double ai, double aj) const
{
    double range = ai + aj;
    if (lubrication) range = std::max(range, lubrication->range(ai, aj));
    if (contact)     range = std::max(range, contact->range(ai, aj));
    if (repulsion)   range = std::max(range, repulsion->range(ai, aj));
    if (attraction)  range = std::max(range, attraction->range(ai, aj));
    return range - ai - aj;
}


std::string ForceModels::summary() const
{
    std::string s = "stokesDrag";
    if (lubrication) s += " lubrication";
    if (contact)     s += " frictionalContact";
    if (repulsion)   s += " electrostaticRepulsion";
    if (attraction)  s += " vanDerWaalsAttraction";
    return s;
}

} // namespace suspension
