#include "ambientFlow.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::ambientFlow> Foam::ambientFlow::New
(
    const dictionary& dict,
    const vector& box,
    const fvMesh* mesh
)
{
    const word flowType(dict.get<word>("type"));

    Info<< "Selecting ambientFlow " << flowType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(flowType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            typeName,
            flowType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return cstrIter()(dict, box, mesh);
}


Foam::autoPtr<Foam::ambientFlow> Foam::ambientFlow::New
(
    const fvMesh& mesh,
    const dictionary& dict
)
{
    return New(dict, mesh.bounds().span(), &mesh);
}


// ************************************************************************* //
