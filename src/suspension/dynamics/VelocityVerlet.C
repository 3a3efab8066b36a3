#include "dynamics/VelocityVerlet.H"
#include "core/Parallel.H"
#include "dynamics/MoveAndWrap.H"

namespace suspension
{

std::size_t VelocityVerlet::predict
(
    Particles& p,
    const LeesEdwardsBox& box,
    double dt
)
{
    return moveAndWrap(p, box, [&p, dt](std::size_t i)   // then (16)
    {
        const Vec3 alpha = p.F[i]/p.m[i];
        p.x[i] += dt*p.u[i] + 0.5*dt*dt*alpha;      // (15a)
        p.u[i] += 0.5*dt*alpha;                     // (15b)
        p.omega[i] += 0.5*dt*p.T[i]/p.I[i];
    });
}


void VelocityVerlet::correct(Particles& p, double dt)
{
    const std::size_t N = p.size();

    #pragma omp parallel for schedule(static) if(threaded(N))
    for (std::size_t i = 0; i < N; ++i)
    {
        p.u[i] += 0.5*dt*p.F[i]/p.m[i];             // (15d)
        p.omega[i] += 0.5*dt*p.T[i]/p.I[i];
    }
}

} // namespace suspension
