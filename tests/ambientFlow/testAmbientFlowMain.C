// GoogleTest main for the ambientFlow tests: OpenFOAM fatal errors become
// catchable Foam::error / Foam::IOerror exceptions instead of exiting.
#include "error.H"

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    Foam::FatalError.throwExceptions();
    Foam::FatalIOError.throwExceptions();
    return RUN_ALL_TESTS();
}
