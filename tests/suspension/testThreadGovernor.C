// ThreadGovernor on synthetic step times: a machine where two threads are
// faster keeps them, one where they are slower (a core taken by another
// program) drops to one, a change of load during the run is followed, and
// the probes of a losing count cost little and come ever less often.
#include "core/ThreadGovernor.H"

#include <gtest/gtest.h>

#include <functional>

using suspension::ThreadGovernor;

namespace
{

//- Steps `steps` steps whose wall seconds stepTime(threads) gives; the steps
//  taken with each count and their total time
struct Steps
{
    long steps[3] = {0, 0, 0};
    double seconds = 0;
};

Steps run
(
    ThreadGovernor& g,
    long steps,
    const std::function<double(int)>& stepTime
)
{
    Steps r;
    for (long k = 0; k < steps; ++k)
    {
        const int n = g.threads();
        const double t = stepTime(n);
        ++r.steps[n];
        r.seconds += t;
        g.record(t);
    }
    return r;
}

} // End anonymous namespace


TEST(ThreadGovernor, KeepsTwoThreadsWhereTheyAreFaster)
{
    ThreadGovernor g(2);
    const Steps r = run(g, 20000, [](int n) { return n == 2 ? 0.01 : 0.015; });
    EXPECT_EQ(g.inUse(), 2);
    EXPECT_EQ(g.switches(), 1u);      // from the first window's one thread
    // The first window and the probes of one thread: under 2 % of the steps
    EXPECT_LT(r.steps[1], 0.02*20000);
}


TEST(ThreadGovernor, DropsToOneThreadWhereTwoAreSlower)
{
    // Two threads 33 times slower (spinning at barriers beside another
    // program): the run must not be slower than one thread by more than
    // the probes, which end early
    ThreadGovernor g(2);
    const auto time = [](int n) { return n == 2 ? 0.33 : 0.01; };
    const Steps r = run(g, 20000, time);
    EXPECT_EQ(g.inUse(), 1);
    EXPECT_EQ(g.switches(), 0u);
    EXPECT_LT(r.seconds, 1.05*20000*0.01);
}


TEST(ThreadGovernor, FollowsAChangeOfLoad)
{
    ThreadGovernor g(2);
    bool busy = false;
    const auto time = [&](int n)
    {
        return n == 2 ? (busy ? 0.02 : 0.006) : 0.01;
    };
    run(g, 2000, time);
    EXPECT_EQ(g.inUse(), 2);
    busy = true;
    run(g, 2000, time);
    EXPECT_EQ(g.inUse(), 1);
    busy = false;
    // the probes of two threads have backed off: give them time
    run(g, 20000, time);
    EXPECT_EQ(g.inUse(), 2);
}


TEST(ThreadGovernor, OneThreadNeverProbes)
{
    ThreadGovernor g(1);
    const Steps r = run(g, 1000, [](int) { return 0.01; });
    EXPECT_EQ(r.steps[1], 1000);
    EXPECT_EQ(g.switches(), 0u);
}


TEST(ThreadGovernor, NoiseWithinTheMarginDoesNotSwitch)
{
    // Steps that vary by 8 % (rebuilds, iterations) with one and two
    // threads equally fast
    ThreadGovernor g(2);
    long k = 0;
    run(g, 20000, [&](int) { return (++k % 7 == 0) ? 0.0108 : 0.01; });
    EXPECT_EQ(g.switches(), 0u);
}


TEST(ThreadGovernor, RefusesBadParameters)
{
    EXPECT_THROW(ThreadGovernor(0), std::invalid_argument);
    ThreadGovernor::Params p;
    p.maxInterval = p.firstInterval - 1;
    EXPECT_THROW(ThreadGovernor(2, p), std::invalid_argument);
}
