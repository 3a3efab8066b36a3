// ConjugateGradient on a dense symmetric positive-definite matrix: the
// solve, and the start along a predictor direction (ConjugateGradient.H);
// the outcome of a solve that cannot converge, never read as converged
#include "dynamics/ConjugateGradient.H"

#include <Eigen/Core>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace suspension;

namespace
{
    //- A = Q^T diag(1 ... 1e3) Q for a random orthogonal Q, with the
    //  Jacobi preconditioner, in the Operator interface of the solver
    struct DenseOperator
    {
        Eigen::MatrixXd A;

        explicit DenseOperator(int n)
        {
            std::mt19937 gen(5);
            std::normal_distribution<double> normal;
            Eigen::MatrixXd M(n, n);
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    M(i, j) = normal(gen);
            const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(M).householderQ();
            Eigen::VectorXd lambda(n);
            for (int i = 0; i < n; ++i)
                lambda(i) = std::pow(1e3, double(i)/(n - 1));
            A = Q.transpose()*lambda.asDiagonal()*Q;
        }

        void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const { y = A*x; }

        void precondition
        (
            const Eigen::VectorXd& r,
            Eigen::VectorXd& z,
            Eigen::Index start,
            Eigen::Index n
        ) const
        {
            z.segment(start, n) =
                r.segment(start, n).cwiseQuotient(A.diagonal().segment(start, n));
        }

        //- The A-norm of the error of x
        double error(const Eigen::VectorXd& x, const Eigen::VectorXd& exact) const
        {
            const Eigen::VectorXd e = x - exact;
            return std::sqrt(e.dot(A*e));
        }
    };
}


TEST(ConjugateGradient, SolvesToTheTolerance)
{
    const int n = 60;
    const DenseOperator op(n);
    const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(n, -1, 2);
    const Eigen::VectorXd b = op.A*exact;
    ConjugateGradient::Params params;
    params.tolerance = 1e-10;
    ConjugateGradient cg(params);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    const ConjugateGradient::Result r = cg.solve(op, b, x);
    EXPECT_TRUE(r.converged);
    EXPECT_LE((op.A*x - b).norm(), 1e-10*b.norm()*1.0001);
    EXPECT_LT((x - exact).norm(), 1e-6*exact.norm());
}


TEST(ConjugateGradient, PredictorStartIsTheEnergyMinimumAlongIt)
{
    // The start x + theta d with theta = d.r/(d.A d): d along the error
    // (of any length and sign) lands on the solution, with no iteration;
    // for a random d that point is no farther from the solution in the
    // A-norm than x, and the solve still converges to the solution; a
    // zero d (the first step) changes nothing
    const int n = 40;
    const DenseOperator op(n);
    const Eigen::VectorXd exact = Eigen::VectorXd::LinSpaced(n, 1, -3);
    const Eigen::VectorXd b = op.A*exact;
    ConjugateGradient::Params params;
    params.tolerance = 1e-8;
    ConjugateGradient cg(params);

    const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(n, 0.5);
    for (const double scale : {1.0, -5.0, 1e-3})
    {
        const Eigen::VectorXd d = scale*(exact - x0);
        Eigen::VectorXd x = x0;
        const ConjugateGradient::Result r = cg.solve(op, b, x, &d);
        EXPECT_TRUE(r.converged);
        EXPECT_EQ(r.iterations, 0u) << "scale " << scale;
        EXPECT_LT((x - exact).norm(), 1e-8*exact.norm()) << "scale " << scale;
    }

    std::mt19937 gen(9);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 5; ++trial)
    {
        Eigen::VectorXd d(n);
        for (int i = 0; i < n; ++i) d(i) = normal(gen);
        const Eigen::VectorXd r0 = b - op.A*x0;
        const double theta = d.dot(r0)/d.dot(op.A*d);
        EXPECT_LE(op.error(x0 + theta*d, exact), op.error(x0, exact));

        Eigen::VectorXd x = x0;
        const ConjugateGradient::Result r = cg.solve(op, b, x, &d);
        EXPECT_TRUE(r.converged);
        EXPECT_LT((x - exact).norm(), 1e-5*exact.norm());
    }

    // A zero direction (the first step) is no direction
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd x = x0, y = x0;
    const ConjugateGradient::Result a = cg.solve(op, b, x, &zero);
    const ConjugateGradient::Result c = cg.solve(op, b, y);
    EXPECT_EQ(a.iterations, c.iterations);
    EXPECT_EQ(x, y);
}


namespace
{
    const double NaN = std::numeric_limits<double>::quiet_NaN();

    //- The dense operator with its product spoilt: NaN in entry `bad` of
    //  every product
    struct NaNOperator
    :
        DenseOperator
    {
        Eigen::Index bad;

        NaNOperator(int n, Eigen::Index bad) : DenseOperator(n), bad(bad) {}

        void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const
        {
            DenseOperator::apply(x, y);
            y(bad) = NaN;
        }
    };

    //- diag(1, ..., 1, -1) with the identity as preconditioner
    struct IndefiniteOperator
    {
        Eigen::VectorXd d;

        explicit IndefiniteOperator(int n) : d(Eigen::VectorXd::Ones(n)) { d(n - 1) = -1; }

        void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const { y = d.cwiseProduct(x); }

        void precondition
        (
            const Eigen::VectorXd& r,
            Eigen::VectorXd& z,
            Eigen::Index start,
            Eigen::Index n
        ) const
        {
            z.segment(start, n) = r.segment(start, n);
        }
    };
}


TEST(ConjugateGradient, NonFiniteRightHandSideIsNotConverged)
{
    // A NaN or an infinity in b: not converged, said so, x as given
    const int n = 30;
    const DenseOperator op(n);
    ConjugateGradient cg{ConjugateGradient::Params()};
    for (const double bad : {NaN, std::numeric_limits<double>::infinity()})
    {
        Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
        b(11) = bad;
        const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(n, 0.5);
        Eigen::VectorXd x = x0;
        const ConjugateGradient::Result r = cg.solve(op, b, x);
        EXPECT_FALSE(r.converged) << bad;
        EXPECT_EQ(r.outcome, ConjugateGradient::Outcome::nonFiniteRightHandSide) << bad;
        EXPECT_EQ(x, x0) << bad;
    }
}


TEST(ConjugateGradient, NonFiniteResidualIsNotConverged)
{
    // An operator that returns a NaN: not converged at the initial
    // residual. A NaN in the initial guess: the same, and the start along
    // the predictor skipped, so that x is as given (its one NaN where it
    // was, for the caller to find)
    const int n = 30;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
    ConjugateGradient cg{ConjugateGradient::Params()};

    const NaNOperator spoilt(n, 4);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    ConjugateGradient::Result r = cg.solve(spoilt, b, x);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.outcome, ConjugateGradient::Outcome::nonFiniteResidual);
    EXPECT_EQ(r.iterations, 0u);

    const DenseOperator op(n);
    Eigen::VectorXd x0 = Eigen::VectorXd::Constant(n, 0.5);
    x0(7) = NaN;
    const Eigen::VectorXd d = Eigen::VectorXd::Constant(n, 0.1);
    x = x0;
    r = cg.solve(op, b, x, &d);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.outcome, ConjugateGradient::Outcome::nonFiniteResidual);
    for (int i = 0; i < n; ++i)
    {
        if (i != 7)
        {
            EXPECT_EQ(x(i), x0(i)) << "entry " << i;
        }
    }
    EXPECT_TRUE(std::isnan(x(7)));
}


TEST(ConjugateGradient, IndefiniteOperatorIsNotPositiveDefinite)
{
    // b along the negative eigenvector: p.A p < 0 at the first iteration
    const int n = 10;
    const IndefiniteOperator op(n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    b(n - 1) = 1;
    ConjugateGradient cg{ConjugateGradient::Params()};
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    const ConjugateGradient::Result r = cg.solve(op, b, x);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.outcome, ConjugateGradient::Outcome::notPositiveDefinite);
    EXPECT_EQ(r.iterations, 0u);
}


TEST(ConjugateGradient, MaxIterationsIsNotConverged)
{
    const int n = 60;
    const DenseOperator op(n);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
    ConjugateGradient::Params params;
    params.tolerance = 1e-12;
    params.maxIterations = 3;
    ConjugateGradient cg(params);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    const ConjugateGradient::Result r = cg.solve(op, b, x);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.outcome, ConjugateGradient::Outcome::maxIterations);
    EXPECT_EQ(r.iterations, 3u);
    EXPECT_GT(r.residual, params.tolerance);
}
