#include "core/ThreadGovernor.H"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace suspension
{

ThreadGovernor::ThreadGovernor(int maxThreads)
:
    ThreadGovernor(maxThreads, Params())
{}


ThreadGovernor::ThreadGovernor(int maxThreads, const Params& params)
:
    params_(params),
    max_(maxThreads),
    inUse_(1),
    probe_(1),
    direction_(1),
    interval_(params.firstInterval),
    sinceProbe_(params.firstInterval - 1),
    reference_(0),
    steps_(0),
    seconds_(0),
    switches_(0)
{
    if
    (
        maxThreads < 1 || params.minSteps < 1 || !(params.minSeconds >= 0)
     || !(params.margin >= 0) || params.firstInterval < 1
     || params.maxInterval < params.firstInterval
    )
    {
        throw std::invalid_argument
        (
            "ThreadGovernor: need maxThreads >= 1, minSteps >= 1, minSeconds"
            " >= 0, margin >= 0, 1 <= firstInterval <= maxInterval; got"
            " maxThreads " + std::to_string(maxThreads)
        );
    }
}


int ThreadGovernor::neighbour(int d) const
{
    return d < 0 ? std::max(1, inUse_/2) : std::min(max_, 2*inUse_);
}


void ThreadGovernor::record(double seconds)
{
    ++steps_;
    seconds_ += seconds;

    const bool probing = probe_ != inUse_;
    const bool full = steps_ >= params_.minSteps && seconds_ >= params_.minSeconds;
    const bool lost =
        probing && reference_ > 0
     && seconds_ > (1 + params_.margin)*reference_*std::max(steps_, params_.minSteps);
    if (full || lost)
    {
        endWindow();
    }
}


void ThreadGovernor::endWindow()
{
    const double perStep = seconds_/steps_;
    if (probe_ == inUse_)
    {
        reference_ = perStep;
        ++sinceProbe_;
    }
    else
    {
        if (perStep*(1 + params_.margin) < reference_)
        {
            // Confirmed by the next probe, of the count it replaces, after
            // a single window: a lucky window is undone at once
            direction_ = probe_ < inUse_ ? 1 : -1;
            inUse_ = probe_;
            reference_ = perStep;
            interval_ = 1;
            ++switches_;
        }
        else
        {
            interval_ = std::min
            (
                params_.maxInterval, std::max(params_.firstInterval, 2*interval_)
            );
            direction_ = -direction_;
        }
        sinceProbe_ = 0;
    }

    // The next window: a probe when one is due and there is a neighbour
    probe_ = inUse_;
    if (sinceProbe_ >= interval_ && max_ > 1)
    {
        int d = direction_;
        if (neighbour(d) == inUse_)
        {
            d = -d;
        }
        if (neighbour(d) != inUse_)
        {
            probe_ = neighbour(d);
            direction_ = d;
        }
    }
    steps_ = 0;
    seconds_ = 0;
}

} // namespace suspension
