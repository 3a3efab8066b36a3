#include "coarseGraining.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::coarseGraining::spread
(
    const UList<point>& x,
    const UList<Type>& Q,
    const scalar offset,
    GeometricField<Type, fvPatchField, volMesh>& field
) const
{
    const vector& L = grid_.box();
    // The amounts of each grid cell, over all processors: a kernel reaches
    // cells of other processors
    List<Type> amount(grid_.size(), Zero);

    DynamicList<label> ix, iy, iz;
    DynamicList<scalar> wx, wy, wz;
    DynamicList<label> cells;
    DynamicList<scalar> w;
    forAll(x, i)
    {
        cells.clear();
        w.clear();
        weights(2, x[i].z(), true, iz, wz);
        // The particle and its images across y, shifted in x by the
        // Lees-Edwards offset
        for (label m = -1; m <= 1; ++m)
        {
            weights(1, x[i].y() + m*L.y(), false, iy, wy);
            if (iy.empty())
            {
                continue;
            }
            scalar xm = x[i].x() + m*offset;
            xm -= L.x()*std::floor(xm/L.x());
            weights(0, xm, true, ix, wx);
            forAll(iz, c)
            {
                forAll(iy, b)
                {
                    forAll(ix, a)
                    {
                        cells.append(grid_.index(ix[a], iy[b], iz[c]));
                        w.append(wx[a]*wy[b]*wz[c]);
                    }
                }
            }
        }
        scalar total = 0;
        for (const scalar wk : w)
        {
            total += wk;
        }
        forAll(cells, k)
        {
            amount[cells[k]] += (w[k]/total)*Q[i];
        }
    }
    grid_.sumOverProcessors(amount);
    Field<Type>& q = field.primitiveFieldRef();
    forAll(q, celli)
    {
        q[celli] = amount[grid_.index()[celli]];
    }
    q /= field.mesh().V().field();
    field.correctBoundaryConditions();
}


// ************************************************************************* //
