// Compiled with OpenFOAM's include directories and libambientFlow's own, but
// not the engine's or Eigen's (tests/ambientFlow/CMakeLists.txt): any
// OpenFOAM application can include the ambient flows (ctest
// AmbientFlowHeadersNeedNoEngine)
#include "ambientFlow.H"
#include "uniformShear.H"
#include "wavyShear.H"
#include "meshSampled.H"

//- The shear rate d_y U_x at p, through the OpenFOAM types only
Foam::scalar ambientFlowHeadersAloneShearRate
(
    const Foam::ambientFlow& flow,
    const Foam::point& p
)
{
    Foam::ambientFlowSample values;
    return flow.sample(p, values) ? values.gradU.yx() : 0;
}
