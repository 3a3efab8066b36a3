#include "core/Particles.H"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace suspension
{

namespace
{
    template<class T>
    void permuteArray(std::vector<T>& v, const std::vector<std::size_t>& order)
    {
        std::vector<T> tmp(order.size());
        for (std::size_t k = 0; k < order.size(); ++k)
        {
            tmp[k] = v[order[k]];
        }
        v.swap(tmp);
    }
}


void Particles::add
(
    const Vec3& position,
    double radius,
    double rho,
    std::int64_t label
)
{
    if (!(radius > 0))
    {
        throw std::invalid_argument
        (
            "Particles::add: radius must be positive, got " + std::to_string(radius)
        );
    }
    const double mass = 4.0/3.0*pi*radius*radius*radius*rho;
    x.push_back(position);
    u.push_back(Vec3::Zero());
    omega.push_back(Vec3::Zero());
    F.push_back(Vec3::Zero());
    T.push_back(Vec3::Zero());
    dudt.push_back(Vec3::Zero());
    domegadt.push_back(Vec3::Zero());
    a.push_back(radius);
    m.push_back(mass);
    I.push_back(0.4*mass*radius*radius);
    id.push_back(label);
    if (!ghost.empty())
    {
        ghost.push_back(0);
    }
}


void Particles::permute(const std::vector<std::size_t>& order)
{
    permuteArray(x, order);
    permuteArray(u, order);
    permuteArray(omega, order);
    permuteArray(F, order);
    permuteArray(T, order);
    permuteArray(dudt, order);
    permuteArray(domegadt, order);
    permuteArray(a, order);
    permuteArray(m, order);
    permuteArray(I, order);
    permuteArray(id, order);
    if (!ghost.empty())
    {
        permuteArray(ghost, order);
    }
}


double Particles::maxRadius() const
{
    return a.empty() ? 0.0 : *std::max_element(a.begin(), a.end());
}


double Particles::solidVolume() const
{
    double V = 0;
    for (double r : a)
    {
        V += 4.0/3.0*pi*r*r*r;
    }
    return V;
}

} // namespace suspension
