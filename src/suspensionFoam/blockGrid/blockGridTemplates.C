#include "blockGrid.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
void Foam::blockGrid::sumOverProcessors(List<Type>& v)
{
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(v, plusEqOp<Type>());
        Pstream::listCombineScatter(v);
    }
}


template<class Type>
Foam::List<Type> Foam::blockGrid::rowMeans(const UList<Type>& f) const
{
    List<Type> mean(n(1), Zero);
    forAll(index_, celli)
    {
        mean[row(celli)] += mesh_.V()[celli]*f[celli];
    }
    sumOverProcessors(mean);
    forAll(mean, j)
    {
        mean[j] /= rowVolume_[j];
    }
    return mean;
}


template<class Type>
Foam::tmp<Foam::GeometricField<Type, Foam::fvPatchField, Foam::volMesh>>
Foam::blockGrid::planeAverage
(
    const GeometricField<Type, fvPatchField, volMesh>& field
) const
{
    const List<Type> mean = rowMeans(field.primitiveField());
    tmp<GeometricField<Type, fvPatchField, volMesh>> tavg
    (
        new GeometricField<Type, fvPatchField, volMesh>
        (
            IOobject
            (
                "planeAverage(" + field.name() + ")",
                field.instance(),
                field.db(),
                IOobject::NO_READ,
                IOobject::NO_WRITE,
                false
            ),
            field
        )
    );
    Field<Type>& avg = tavg.ref().primitiveFieldRef();
    forAll(index_, celli)
    {
        avg[celli] = mean[row(celli)];
    }
    tavg.ref().correctBoundaryConditions();
    return tavg;
}


// ************************************************************************* //
