#include "mpmiceAdapter.H"

#include "addToRunTimeSelectionTable.H"
#include "fvc.H"
#include "surfaceFields.H"
#include "volFields.H"
#include "IOdictionary.H"
#include "dimensionedScalar.H"
#include "pointFields.H"
#include "DynamicList.H"
#include "fixedValuePointPatchFields.H"
#include "GAMGAgglomeration.H"
#include "mpmice_bridge.h"

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
    csv_(),
    exportPrecision_(12),
    sceneFile_(),
    bridge_(nullptr),
    coupled_(false),
    twoWay_(false),
    implicit_(false),
    windows_(0),
    endTime_(0),
    savedTime_(0),
    savedIndex_(0)
{
    read(dict);
    openCsv();
    if (!sceneFile_.empty())
    {
        startCoupling();
    }
}

Foam::functionObjects::mpmiceAdapter::~mpmiceAdapter()
{
    if (bridge_)
    {
        mpmice_bridge_finish(bridge_);
        bridge_ = nullptr;
    }
}

void Foam::functionObjects::mpmiceAdapter::fail(const string& what) const
{
    FatalErrorInFunction
        << "mpmiceAdapter: " << what.c_str() << nl << exit(FatalError);
}

bool Foam::functionObjects::mpmiceAdapter::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);

    sceneFile_ = dict.lookupOrDefault<fileName>("scene", fileName());
    if (!sceneFile_.empty())
    {
        // The scene names the patch and the density; the bridge reads it.
        bridge_ = mpmice_bridge_start(sceneFile_.c_str());
        const char* err = mpmice_bridge_error(bridge_);
        if (err)
        {
            fail(string("cannot join the coupled run: ") + err);
        }
        mpmice_bridge_info info;
        mpmice_bridge_info_get(bridge_, &info);
        coupled_ = info.coupled != 0;
        twoWay_ = info.two_way != 0;
        implicit_ = info.implicit != 0;
        patchName_ = word(info.patch);
        rho_ = info.fluid_density;
    }
    else
    {
        patchName_ = dict.get<word>("patch");
    }
    patchi_ = mesh_.boundaryMesh().findPatchID(patchName_);
    if (patchi_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "mpmiceAdapter: unknown patch '" << patchName_ << "'"
            << (sceneFile_.empty() ? "" : " (coupling.interface.patch of the scene)") << nl
            << "    valid patch names: " << mesh_.boundaryMesh().names()
            << exit(FatalIOError);
    }

    pName_ = dict.lookupOrDefault<word>("p", "p");
    UName_ = dict.lookupOrDefault<word>("U", "U");
    if (sceneFile_.empty())
    {
        rho_ = dict.lookupOrDefault<scalar>("rho", 1.0);
    }
    exportPrecision_ = dict.lookupOrDefault<label>("exportPrecision", 12);
    if (exportPrecision_ < 1 || exportPrecision_ > 17)
    {
        FatalIOErrorInFunction(dict)
            << "mpmiceAdapter: exportPrecision " << exportPrecision_
            << " must lie in 1..17 (significant digits)" << exit(FatalIOError);
    }

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

Foam::vector Foam::functionObjects::mpmiceAdapter::patchForce(const vectorField& f) const
{
    vector force(sum(f));
    reduce(force, sumOp<vector>());
    return force;
}

Foam::tmp<Foam::vectorField>
Foam::functionObjects::mpmiceAdapter::faceForces()
{
    const vectorField& Sf = mesh_.Sf().boundaryField()[patchi_];
    tmp<vectorField> tf(new vectorField(Sf.size(), Zero));
    vectorField& f = tf.ref();
    if (foundObject<volScalarField>(pName_))
    {
        f += lookupObject<volScalarField>(pName_).boundaryField()[patchi_]*Sf;
    }
    if (haveNu_ && foundObject<volVectorField>(UName_))
    {
        const volVectorField& U = lookupObject<volVectorField>(UName_);
        const volTensorField gradU(fvc::grad(U));
        f += Sf & (-nu_*dev(twoSymm(gradU.boundaryField()[patchi_])));
    }
    else if (!notedNoViscous_)
    {
        Info<< type() << " " << name() << ": no " << UName_ << " field or nu;"
            << " viscous force left 0" << endl;
        notedNoViscous_ = true;
    }
    f *= rho_;
    return tf;
}

Foam::scalar Foam::functionObjects::mpmiceAdapter::meshDepth() const
{
    scalar depth = 1;
    if (mesh_.nSolutionD() == 2)
    {
        const Vector<label>& sol = mesh_.solutionD();
        const vector span = mesh_.bounds().span();
        for (direction d = 0; d < 3; ++d)
        {
            if (sol[d] < 0) depth = span[d];
        }
    }
    return depth;
}

void Foam::functionObjects::mpmiceAdapter::exportForces(const vectorField& f) const
{
    List<vectorField> centres(Pstream::nProcs()), forces(Pstream::nProcs());
    centres[Pstream::myProcNo()] = mesh_.boundaryMesh()[patchi_].faceCentres();
    forces[Pstream::myProcNo()] = f;
    Pstream::gatherList(centres);
    Pstream::gatherList(forces);
    if (!Pstream::master()) return;
    const fileName dir = time_.globalPath()/"postProcessing"/name()/time_.timeName();
    mkDir(dir);
    OFstream os(dir/"patchForces.csv");
    os.precision(exportPrecision_);
    os.setf(std::ios::scientific, std::ios::floatfield);
    os  << "#" << nl
        << "# mpmiceAdapter patch force export (the format of CFX-Post's data export)" << nl
        << "# Case: " << time_.globalPath() << nl
        << "# Patch: " << patchName_ << ", time " << time_.timeName() << " s" << nl
        << "# Force = rho (p Sf + Sf . (-nu dev(2 sym grad U))), rho " << rho_ << nl;
    if (mesh_.nSolutionD() == 2)
    {
        os  << "# Depth [m]: " << meshDepth() << nl;
    }
    os  << "#" << nl
        << "# The following variables will be output for all locators:" << nl
        << "# 1 - X [m]" << nl << "# 2 - Y [m]" << nl << "# 3 - Z [m]" << nl
        << "# 4 - Fluid.Force X [N]" << nl << "# 5 - Fluid.Force Y [N]" << nl
        << "# 6 - Fluid.Force Z [N]" << nl << "#" << nl;
    forAll(centres, proc)
    {
        forAll(centres[proc], i)
        {
            const vector& c = centres[proc][i];
            const vector& F = forces[proc][i];
            os  << c.x() << ", " << c.y() << ", " << c.z() << ", "
                << F.x() << ", " << F.y() << ", " << F.z() << nl;
        }
    }
}

void Foam::functionObjects::mpmiceAdapter::startCoupling()
{
    if (Pstream::parRun())
    {
        fail("coupled runs need a serial OpenFOAM solver (Pstream of v1912 takes MPI_COMM_WORLD; see adapters/openfoam/README.md)");
    }
    const polyPatch& pp = mesh_.boundaryMesh()[patchi_];
    const vectorField Cf(pp.faceCentres());
    const pointField& pts = pp.localPoints();
    List<scalar> fc(3*Cf.size()), pc(3*pts.size());
    forAll(Cf, i) { for (direction d = 0; d < 3; ++d) fc[3*i + d] = Cf[i][d]; }
    forAll(pts, i) { for (direction d = 0; d < 3; ++d) pc[3*i + d] = pts[i][d]; }
    const scalar depth = meshDepth();
    if (twoWay_ && !mesh_.foundObject<pointVectorField>("pointDisplacement"))
    {
        fail("two-way coupling moves the mesh: give constant/dynamicMeshDict a displacementLaplacian motion solver "
             "(dynamicMotionSolverFvMesh) and 0/pointDisplacement with a fixedValue on patch " + patchName_);
    }
    endTime_ = time_.endTime().value();
    // The start is the clock's value (a restart's time directory holds it to the last digit;
    // controlDict's startTime only names that directory).
    if (mpmice_bridge_set_patch(bridge_, Cf.size(), fc.cdata(), pts.size(), pc.cdata(), depth,
                                time_.deltaTValue(), time_.value(), endTime_))
    {
        fail(mpmice_bridge_error(bridge_));
    }
    if (implicit_)
    {
        // Time::run() executes function objects after the last step outside its loop, where a
        // repeated window could not be solved again. One window more keeps the last one inside;
        // execute() ends the run once the real last window is accepted.
        const_cast<Time&>(time_).setEndTime(endTime_ + time_.deltaTValue());
    }
    Info<< type() << " " << name() << ": coupled through patch " << patchName_ << " ("
        << Cf.size() << " faces, " << pts.size() << " points, depth " << depth << " m), "
        << (twoWay_ ? "two-way" : "one-way") << (implicit_ ? ", implicit" : ", explicit") << endl;
    if (implicit_) checkpoint();
}

void Foam::functionObjects::mpmiceAdapter::applyDisplacements(const List<scalar>& d)
{
    pointVectorField& pd =
        const_cast<pointVectorField&>(mesh_.lookupObject<pointVectorField>("pointDisplacement"));
    pointPatchVectorField& bp = pd.boundaryFieldRef()[patchi_];
    if (!isA<fixedValuePointPatchVectorField>(bp))
    {
        fail("pointDisplacement on patch " + patchName_ + " must be fixedValue (the solid sets it)");
    }
    vectorField disp(bp.size());
    forAll(disp, i) { disp[i] = vector(d[3*i], d[3*i + 1], d[3*i + 2]); }
    refCast<fixedValuePointPatchVectorField>(bp) == disp;
}

template<class FieldType>
void Foam::functionObjects::mpmiceAdapter::store(Saved<FieldType>& s)
{
    // The previous checkpoint's copies go first (they are registered fields too).
    s.fields.clear(); s.old.clear();
    const wordList all(mesh_.sortedNames<FieldType>());
    DynamicList<word> keep;
    forAll(all, i)
    {
        if (!all[i].endsWith("_0") && all[i].find("_mpmiceSaved") == string::npos) keep.append(all[i]);
    }
    const wordList names(keep);
    const label n = names.size();
    s.fields.setSize(n); s.old.setSize(n); s.names.setSize(n); s.indices.setSize(n);
    label k = 0;
    forAll(names, i)
    {
        const FieldType& f = mesh_.lookupObject<FieldType>(names[i]);
        s.names[k] = names[i];
        s.indices[k] = f.timeIndex();
        s.fields.set(k, new FieldType(names[i] + "_mpmiceSaved", f));
        s.fields[k].writeOpt() = IOobject::NO_WRITE;  // never in a time directory
        if (f.nOldTimes())
        {
            s.old.set(k, new FieldType(names[i] + "_mpmiceSaved0", f.oldTime()));
            s.old[k].writeOpt() = IOobject::NO_WRITE;
        }
        ++k;
    }
}

template<class FieldType>
void Foam::functionObjects::mpmiceAdapter::reload(Saved<FieldType>& s)
{
    forAll(s.names, k)
    {
        if (!mesh_.foundObject<FieldType>(s.names[k])) continue;
        FieldType& f = const_cast<FieldType&>(mesh_.lookupObject<FieldType>(s.names[k]));
        // The time index first: with it, oldTime() does not store the current values again.
        f.timeIndex() = s.indices[k];
        if (s.old.set(k) && f.nOldTimes())
        {
            f.oldTime() == s.old[k];
        }
        f == s.fields[k];
    }
}

void Foam::functionObjects::mpmiceAdapter::checkpoint()
{
    savedTime_ = time_.value();
    savedIndex_ = time_.timeIndex();
    store(vsf_); store(vvf_); store(ssf_); store(svf_);
}

// The mesh needs no checkpoint: displacementLaplacian places the points at points0 + the
// displacement (absolute), and when the window is repeated at the same time index, polyMesh
// keeps its old points and fvMesh its old volumes from the first attempt (both store them
// once per time index), so the mesh flux sweeps from the window's start again.
void Foam::functionObjects::mpmiceAdapter::restore()
{
    const_cast<Time&>(time_).setTime(savedTime_, savedIndex_);
    reload(vsf_); reload(vvf_); reload(ssf_); reload(svf_);
}

bool Foam::functionObjects::mpmiceAdapter::execute()
{
    // One pass over the patch per step: the face forces feed the coupling and the log.
    const vectorField f(faceForces());
    // GAMG keeps its agglomeration on the mesh (cacheAgglomeration, on by default) while the mesh
    // moves: an uninterrupted run would solve with one built from an earlier geometry than a
    // restart, which builds it from the time directory's mesh, and the solvers converge to a
    // different round-off (implicit windows: 1.3e-4 in p between the two runs). Dropped after
    // each step, every step builds it from its own mesh in both runs (then 5.8e-15).
    MeshObject<lduMesh, GeometricMeshObject, GAMGAgglomeration>::Delete(mesh_);
    if (bridge_ && coupled_)
    {
        List<scalar> ff(3*f.size());
        forAll(f, i) { for (direction d = 0; d < 3; ++d) ff[3*i + d] = f[i][d]; }
        const label nPoints = mesh_.boundaryMesh()[patchi_].nPoints();
        List<scalar> disp(3*nPoints, 0.0);
        const bool last = time_.value() > endTime_ - 0.5*time_.deltaTValue();
        int action = 0, iterations = 1;
        if (mpmice_bridge_exchange(bridge_, time_.value(), time_.deltaTValue(), last ? 1 : 0, ff.cdata(),
                                   disp.data(), &action, &iterations))
        {
            fail(mpmice_bridge_error(bridge_));
        }
        if (twoWay_) applyDisplacements(disp);
        if (action == 1)
        {
            Info<< type() << ": window ending at t = " << time_.value() << " repeated (iteration "
                << iterations << ")" << endl;
            restore();
            return true;
        }
        ++windows_;
        if (implicit_ && last)
        {
            const_cast<Time&>(time_).setEndTime(time_.value());
        }
        else if (implicit_)
        {
            checkpoint();
        }
        if (mpmice_bridge_write_due(bridge_))
        {
            // The solid writes a restart checkpoint at this window: the time directory of the
            // same time, with the displacements just received as pointDisplacement's patch
            // value (what the next window moves the mesh by), so `coupler run --restart`
            // resumes the fluid from here (startFrom startTime) as if it had not stopped.
            Info<< type() << ": restart state written at t = " << time_.timeName()
                << " (the solid's checkpoint)" << endl;
            const_cast<Time&>(time_).writeNow();
        }
    }
    if (!bridge_ && (time_.writeTime() || time_.value() > time_.endTime().value() - 0.5*time_.deltaTValue()))
    {
        exportForces(f);
    }
    const vector F = patchForce(f);
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
