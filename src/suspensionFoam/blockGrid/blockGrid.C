#include "blockGrid.H"
#include "ListListOps.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Values v sorted and merged where closer than tol
Foam::scalarList distinct(Foam::scalarList v, const Foam::scalar tol)
{
    std::sort(v.begin(), v.end());
    Foam::DynamicList<Foam::scalar> out;
    for (const Foam::scalar x : v)
    {
        if (out.empty() || x - out.last() > tol)
        {
            out.append(x);
        }
    }
    return Foam::scalarList(std::move(out));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blockGrid::blockGrid
(
    const fvMesh& mesh,
    const vector& box,
    const string& user
)
:
    mesh_(mesh),
    L_(box),
    edges_(),
    cellOf_(),
    index_(),
    rowVolume_()
{
    const fileName meshDir =
        mesh_.time().path()/mesh_.facesInstance()/mesh_.meshDir();
    const pointField& points = mesh_.points();
    const scalar tol = 1e-6*cmptMin(L_);
    const label nCells = mesh_.nCells();
    const string need =
        user + " needs the mesh of blockMesh with one block (axis-aligned"
        " hexahedra on one grid, any grading) spanning the box";

    // Each cell an axis-aligned box: its volume that of its bounding box
    List<boundBox> cellBox(nCells);
    FixedList<scalarList, 3> planes;
    for (direction d = 0; d < 3; ++d)
    {
        planes[d].setSize(2*nCells);
    }
    forAll(cellBox, celli)
    {
        cellBox[celli] = boundBox(points, mesh_.cellPoints()[celli], false);
        const boundBox& bb = cellBox[celli];
        if (mag(bb.volume() - mesh_.V()[celli]) > 1e-9*bb.volume())
        {
            FatalIOErrorInFunction(meshDir)
                << "Cell " << celli << " of the mesh in " << meshDir << " is"
                << " not an axis-aligned hexahedron: " << need.c_str() << nl
                << exit(FatalIOError);
        }
        for (direction d = 0; d < 3; ++d)
        {
            planes[d][2*celli] = bb.min()[d];
            planes[d][2*celli + 1] = bb.max()[d];
        }
    }

    // The planes of every processor's cells (in a parallel run each holds
    // part of the grid)
    label n[3];
    for (direction d = 0; d < 3; ++d)
    {
        List<scalarList> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = distinct(planes[d], tol);
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        edges_[d] = distinct
        (
            ListListOps::combine<scalarList>(all, accessOp<scalarList>()),
            tol
        );
        n[d] = edges_[d].size() - 1;
        if (mag(edges_[d].first()) > tol || mag(edges_[d].last() - L_[d]) > tol)
        {
            FatalIOErrorInFunction(meshDir)
                << "The mesh in " << meshDir << " spans ["
                << edges_[d].first() << ", " << edges_[d].last() << "] in"
                << " direction " << label(d) << ", the box [0, " << L_[d]
                << "]: " << need.c_str() << nl << exit(FatalIOError);
        }
        edges_[d].first() = 0;
        edges_[d].last() = L_[d];
    }
    const label nTotal = returnReduce(nCells, sumOp<label>());
    if (n[0]*n[1]*n[2] != nTotal)
    {
        FatalIOErrorInFunction(meshDir)
            << "The " << nTotal << " cells of the mesh in " << meshDir
            << " do not lie on one grid (" << n[0] << " x " << n[1] << " x "
            << n[2] << " planes): " << need.c_str() << nl
            << exit(FatalIOError);
    }

    cellOf_.setSize(nTotal, -1);
    index_.setSize(nCells);
    rowVolume_.setSize(n[1], 0);
    forAll(cellBox, celli)
    {
        label ijk[3];
        for (direction d = 0; d < 3; ++d)
        {
            const scalarList& e = edges_[d];
            ijk[d] = label
            (
                std::upper_bound
                (
                    e.begin(), e.end(), cellBox[celli].min()[d] + 0.5*tol
                )
              - e.begin()
            ) - 1;
        }
        const label g = ijk[0] + n[0]*(ijk[1] + n[1]*ijk[2]);
        bool oneInterval = cellOf_[g] < 0;
        for (direction d = 0; d < 3; ++d)
        {
            oneInterval = oneInterval
             && mag(cellBox[celli].max()[d] - edges_[d][ijk[d] + 1]) <= tol;
        }
        if (!oneInterval)
        {
            FatalIOErrorInFunction(meshDir)
                << "Cell " << celli << " of the mesh in " << meshDir
                << " (" << cellBox[celli] << ") is not one cell of the grid"
                << " of its planes: " << need.c_str() << nl
                << exit(FatalIOError);
        }
        cellOf_[g] = celli;
        index_[celli] = g;
        rowVolume_[ijk[1]] += mesh_.V()[celli];
    }

    // Each grid cell on one processor: the count above then leaves none out
    labelList held(nTotal, 0);
    for (const label g : index_)
    {
        held[g] = 1;
    }
    sumOverProcessors(held);
    forAll(held, g)
    {
        if (held[g] != 1)
        {
            FatalIOErrorInFunction(meshDir)
                << "Cell " << g << " of the grid of the mesh in " << meshDir
                << " is held by " << held[g] << " processors: " << need.c_str()
                << nl << exit(FatalIOError);
        }
    }
    sumOverProcessors(rowVolume_);
}


// ************************************************************************* //
