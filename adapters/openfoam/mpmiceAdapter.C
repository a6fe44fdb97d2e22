#include "mpmiceAdapter.H"

#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "surfaceFields.H"
#include "volFields.H"
#include "IOdictionary.H"
#include "dimensionedScalar.H"

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(mpmiceAdapter, 0);
    addToRunTimeSelectionTable(functionObject, mpmiceAdapter, dictionary);
}
}

Foam::functionObjects::mpmiceAdapter::mpmiceAdapter
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    patchName_(),
    patchi_(-1),
    pName_("p"),
    UName_("U"),
    rho_(1),
    haveNu_(false),
    nu_(0),
    notedNoViscous_(false),
    csv_()
{
    read(dict);
    openCsv();
}

bool Foam::functionObjects::mpmiceAdapter::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);

    patchName_ = dict.get<word>("patch");
    patchi_ = mesh_.boundaryMesh().findPatchID(patchName_);
    if (patchi_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "mpmiceAdapter: unknown patch '" << patchName_ << "'" << nl
            << "    valid patch names: " << mesh_.boundaryMesh().names()
            << exit(FatalIOError);
    }

    pName_ = dict.lookupOrDefault<word>("p", "p");
    UName_ = dict.lookupOrDefault<word>("U", "U");
    rho_ = dict.lookupOrDefault<scalar>("rho", 1.0);

    haveNu_ = false;
    if (dict.found("nu"))
    {
        nu_ = dict.get<scalar>("nu");
        haveNu_ = true;
    }
    else if (mesh_.foundObject<IOdictionary>("transportProperties"))
    {
        const IOdictionary& tp =
            mesh_.lookupObject<IOdictionary>("transportProperties");
        if (tp.found("nu"))
        {
            nu_ = dimensionedScalar("nu", dimViscosity, tp).value();
            haveNu_ = true;
        }
    }
    return true;
}

void Foam::functionObjects::mpmiceAdapter::openCsv()
{
    if (!Pstream::master()) return;
    const fileName dir = time_.globalPath()/"postProcessing"/name();
    mkDir(dir);
    csv_.reset(new OFstream(dir/"forces.csv"));
    csv_().precision(12);
    csv_() << "time,Fx,Fy,Fz" << endl;
}

Foam::vector Foam::functionObjects::mpmiceAdapter::patchForce()
{
    vector force(Zero);

    const vectorField& Sf = mesh_.Sf().boundaryField()[patchi_];

    if (foundObject<volScalarField>(pName_))
    {
        const scalarField& pb =
            lookupObject<volScalarField>(pName_).boundaryField()[patchi_];
        force += sum(pb*Sf);
    }

    if (haveNu_ && foundObject<volVectorField>(UName_))
    {
        const volVectorField& U = lookupObject<volVectorField>(UName_);
        const volTensorField gradU(fvc::grad(U));
        const symmTensorField devR
        (
            -nu_*dev(twoSymm(gradU.boundaryField()[patchi_]))
        );
        force += sum(Sf & devR);
    }
    else if (!notedNoViscous_)
    {
        Info<< type() << " " << name() << ": no " << UName_ << " field or nu;"
            << " viscous force left 0" << endl;
        notedNoViscous_ = true;
    }

    reduce(force, sumOp<vector>());
    return rho_*force;
}

bool Foam::functionObjects::mpmiceAdapter::execute()
{
    const vector F = patchForce();
    if (csv_.valid())
    {
        csv_() << time_.timeOutputValue() << ',' << F.x() << ',' << F.y() << ','
               << F.z() << endl;
    }
    return true;
}

bool Foam::functionObjects::mpmiceAdapter::write()
{
    return true;
}
