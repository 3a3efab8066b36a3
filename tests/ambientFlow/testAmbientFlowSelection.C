// Run-time selection of ambientFlow from a dictionary, and the Foam::IOerror
// that each bad input raises, naming the entry and the dictionary.
#include "testAmbientFlowTools.H"
#include "uniformShear.H"
#include "wavyShear.H"

using namespace Foam;
using ambientFlowTest::flowDict;
using ambientFlowTest::ioErrorOf;
using ambientFlowTest::makeFlow;
using ambientFlowTest::contains;

namespace
{

const vector box(10, 12, 8);

//- The IOerror raised when selecting from entries in box b
std::string selectionError(const std::string& entries, const vector& b = box)
{
    return ioErrorOf([&]() { makeFlow(entries, b); });
}

} // End anonymous namespace


TEST(AmbientFlowSelection, SelectsUniformShear)
{
    const autoPtr<ambientFlow> flow
    (
        makeFlow("type uniformShear; shearRate -2.5;", box)
    );
    EXPECT_EQ(flow->type(), "uniformShear");
    EXPECT_TRUE(isA<uniformShear>(*flow));
    EXPECT_EQ(flow->shearRate(), -2.5);
    EXPECT_EQ(flow->box(), box);
}


TEST(AmbientFlowSelection, SelectsWavyShear)
{
    const autoPtr<ambientFlow> flow
    (
        makeFlow("type wavyShear; shearRate 1; amplitude 20; periods 1;", box)
    );
    EXPECT_EQ(flow->type(), "wavyShear");
    EXPECT_TRUE(isA<wavyShear>(*flow));
    EXPECT_EQ(flow->shearRate(), 1);
    // One period over Ly = 12: the crest is at y = 3
    EXPECT_DOUBLE_EQ(flow->U(point(0, 3, 0)).x(), 3 + 20);
}


TEST(AmbientFlowSelection, UnknownTypeListsTheValidTypes)
{
    const std::string msg = selectionError("type wavyshear; shearRate 1;");
    EXPECT_PRED2(contains, msg, "Unknown ambientFlow type wavyshear");
    EXPECT_PRED2(contains, msg, "uniformShear");
    EXPECT_PRED2(contains, msg, "wavyShear");
    EXPECT_PRED2(contains, msg, "[dictionary ");
    EXPECT_PRED2(contains, msg, "ambientFlow]");
}


TEST(AmbientFlowSelection, MissingTypeIsNamed)
{
    EXPECT_PRED2(contains, selectionError("shearRate 1;"), "'type'");
}


TEST(AmbientFlowSelection, MissingShearRateIsNamed)
{
    for
    (
        const std::string entries :
        {
            "type uniformShear;",
            "type wavyShear; amplitude 20; periods 1;"
        }
    )
    {
        const std::string msg = selectionError(entries);
        EXPECT_PRED2(contains, msg, "'shearRate' not found");
        EXPECT_PRED2(contains, msg, "ambientFlow");
    }
}


TEST(AmbientFlowSelection, NonNumericShearRateIsNamed)
{
    // The parser admits finite numbers only: nan and overflow are rejected
    for (const std::string value : {"nan", "inf", "1e400"})
    {
        SCOPED_TRACE(value);
        EXPECT_PRED2
        (
            contains,
            selectionError("type uniformShear; shearRate " + value + ";"),
            "shearRate"
        );
    }
}


TEST(AmbientFlowSelection, MissingWaveEntriesAreNamed)
{
    EXPECT_PRED2
    (
        contains,
        selectionError("type wavyShear; shearRate 1; periods 1;"),
        "'amplitude' not found"
    );
    EXPECT_PRED2
    (
        contains,
        selectionError("type wavyShear; shearRate 1; amplitude 20;"),
        "'periods' not found"
    );
}


TEST(AmbientFlowSelection, PeriodsMustBeAPositiveInteger)
{
    for (const std::string n : {"0", "-1", "1.5", "0.5"})
    {
        SCOPED_TRACE("periods " + n);
        const std::string msg = selectionError
        (
            "type wavyShear; shearRate 1; amplitude 20; periods " + n + ";"
        );
        EXPECT_PRED2(contains, msg, "Entry 'periods' = " + n);
        EXPECT_PRED2(contains, msg, "must be an integer >= 1");
    }
}


TEST(AmbientFlowSelection, BoxHeightMustBePositive)
{
    for (const scalar Ly : {0.0, -12.0})
    {
        SCOPED_TRACE(Ly);
        const std::string msg = selectionError
        (
            "type wavyShear; shearRate 1; amplitude 20; periods 1;",
            vector(10, Ly, 8)
        );
        EXPECT_PRED2(contains, msg, "box height Ly must be positive");
        EXPECT_PRED2(contains, msg, "[dictionary ");
        EXPECT_PRED2(contains, msg, "ambientFlow]");
    }
}


TEST(AmbientFlowSelection, ErrorsAreCatchableFoamIOerrors)
{
    EXPECT_THROW(makeFlow("type nope;", box), Foam::IOerror);
    EXPECT_THROW
    (
        ambientFlow::New(flowDict("type uniformShear;"), box),
        Foam::IOerror
    );
}



TEST(AmbientFlowSelection, UnknownEntriesAreRejected)
{
    // A stray or misspelt entry would otherwise be ignored: each type names
    // it, with the dictionary and the entries it knows
    struct Case
    {
        std::string entries;
        std::string stray;
        std::string valid;
    };
    const Case cases[] =
    {
        {
            "type uniformShear; shearRate 1; amplitude 20;",
            "amplitude", "shearRate"
        },
        {
            "type wavyShear; shearRate 1; amplitude 20; periods 1; period 2;",
            "period", "periods"
        },
        {
            "type meshSampled; flow { type uniformShear; shearRate 1; }"
            " mesh none;",
            "mesh", "flow"
        },
        {
            "type meshSampled;"
            " flow { type uniformShear; shearRate 1; periods 1; }",
            "periods", "shearRate"
        }
    };
    for (const Case& c : cases)
    {
        SCOPED_TRACE(c.entries);
        const std::string msg = selectionError(c.entries);
        EXPECT_PRED2(contains, msg, "Unknown entry '" + c.stray + "'");
        EXPECT_PRED2(contains, msg, "Valid entries:");
        EXPECT_PRED2(contains, msg, c.valid);
        EXPECT_PRED2(contains, msg, "[dictionary ");
        EXPECT_PRED2(contains, msg, "ambientFlow");
    }
}


TEST(AmbientFlowSelection, AnalyticFlowsAreKnownEverywhere)
{
    const point far(-1e6, 3e6, 1e5);
    for
    (
        const std::string entries :
        {
            "type uniformShear; shearRate 1;",
            "type wavyShear; shearRate 1; amplitude 20; periods 1;"
        }
    )
    {
        SCOPED_TRACE(entries);
        const autoPtr<ambientFlow> flow(makeFlow(entries, box));
        ambientFlowSample values;
        EXPECT_TRUE(flow->sample(far, values));
        EXPECT_EQ(values.U, flow->U(far));
        EXPECT_TRUE(flow->bounds().contains(far));
    }
}
