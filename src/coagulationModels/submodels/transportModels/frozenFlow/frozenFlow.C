/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "frozenFlow.H"
#include "coagulationCloud.H"
#include "caseChecks.H"
#include "flowFields.H"
#include "registerSwitch.H"
#include "interpolation.H"
#include "volPointInterpolation.H"
#include "processorPolyPatch.H"
#include "PstreamBuffers.H"
#include "addToRunTimeSelectionTable.H"

#include <chrono>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace transportModels
{
    defineTypeNameAndDebug(frozenFlow, 0);
    addToRunTimeSelectionTable(transportModel, frozenFlow, dictionary);
}
}
}

int Foam::coagulation::transportModels::frozenFlow::cloudMove
(
    Foam::debug::optimisationSwitch("coagulationCloudMove", 0)
);
registerOptSwitch
(
    "coagulationCloudMove",
    int,
    Foam::coagulation::transportModels::frozenFlow::cloudMove
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::transportModels::frozenFlow::frozenFlow
(
    const dictionary& dict,
    coagulationCloud& cloud
)
:
    transportModel(cloud),
    outcome_(),
    scheme_("cell"),
    maxCo_(0.3),
    UInterp_(),
    cellLength_()
{
    caseChecks::keywords
    (
        dict, {"type", "interpolationSchemes", "maxCo", "flowSeries", "maxGap"}
    );
    if (dict.found("maxGap") && !dict.found("flowSeries"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'maxGap' in " << dict.name() << " is the longest gap"
            << " between a flow series' written times, but there is no"
            << " 'flowSeries'." << nl << "    Remove the entry, or name the"
            << " flow case with 'flowSeries'" << nl << exit(FatalIOError);
    }
    // A flow series (its 'flowSeries' entry) is read by the cloud's
    // flowFields, with the submodels' fields
    series_ = flowFields::of(cloud.mesh()).series();

    // The velocity's interpolation, as a KinematicCloud's
    // solution/interpolationSchemes names it
    if (dict.found("interpolationSchemes"))
    {
        const dictionary& schemes = dict.subDict("interpolationSchemes");
        caseChecks::keywords(schemes, {"U"});
        scheme_ = schemes.get<word>("U");
        if
        (
            !interpolation<vector>::dictionaryConstructorTablePtr_
                ->found(scheme_)
        )
        {
            FatalIOErrorInFunction(schemes)
                << "Entry 'U' of " << schemes.name() << " is '" << scheme_
                << "'; valid interpolation schemes are "
                << interpolation<vector>::dictionaryConstructorTablePtr_
                   ->sortedToc()
                << nl << exit(FatalIOError);
        }
    }
    if (dict.found("maxCo"))
    {
        maxCo_ = caseChecks::positive(dict, "maxCo");
        if (maxCo_ > 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'maxCo' = " << maxCo_ << " in " << dict.name()
                << " must be in (0, 1]" << nl << exit(FatalIOError);
        }
    }
    if (scheme_ != "cell")
    {
        cellLength_ = cbrt(cloud.mesh().V().field());
    }
    Info<< "Transport: velocity interpolation " << scheme_;
    if (scheme_ != "cell")
    {
        Info<< ", segments of at most maxCo " << maxCo_ << " of a cell";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{
    //- How many particles ahead of the move the next is fetched
    constexpr Foam::label prefetchDistance = 8;

    //- Ask for a particle's cache lines before its move reads them (a
    //  hint of GCC and Clang; nothing elsewhere)
    inline void prefetch(const Foam::coagulation::coagulationParticle* p)
    {
        #ifdef __GNUC__
        const char* bytes = reinterpret_cast<const char*>(p);
        for
        (
            std::size_t line = 0;
            line < sizeof(Foam::coagulation::coagulationParticle);
            line += 64
        )
        {
            __builtin_prefetch(bytes + line);
        }
        #else
        (void)p;
        #endif
    }
}


void Foam::coagulation::transportModels::frozenFlow::moveOnThreads
(
    const volVectorField& U,
    coagulationParticle::trackingData& td,
    const scalar dt,
    const streamSeeds::purpose walkStream
)
{
    // What a move did with a particle (zero: kept, so that the array marks
    // the particles to compact away)
    enum : char
    {
        keptByMove = 0, leftByOutflow, droppedByTracking, toProcessor,
        depositedByWalk
    };

    // The threads only read the mesh: its demand-driven parts that tracking
    // uses are built here, serially, first
    const polyMesh& mesh = cloud_.pMesh();
    (void)mesh.tetBasePtIs();
    (void)mesh.cells();
    (void)mesh.cellCentres();
    (void)mesh.geometricD();
    (void)mesh.solutionD();

    // The particles move in cell order (the sort's list positions): the
    // mesh data that the moves of consecutive particles read is then mostly
    // in the cache. Each move changes only its particle, with the stream of
    // its list position, so the order changes no result
    cellParticleIndex& index = cloud_.index();
    index.list(cloud_);
    index.sort(cloud_, mesh.nCells());
    const labelList& cellOrder = index.cellListIndex();
    DynamicList<label>& cells = index.cells();
    DynamicList<coagulationParticle*> leaving;

    const label nPatches = mesh.boundaryMesh().size();
    const bool walks = cloud_.dispersion().active();

    // The list entries [first, end) move: all of them from the start of the
    // step, then, round after round, those another processor handed over
    // (which go on from where they stopped)
    label first = 0;
    label rounds = 0;
    constexpr label maxExchangeRounds = 1000;
    for (bool fresh = true; ; fresh = false)
    {
        const label nParticles = index.particles().size();
        outcome_.assign(nParticles, keptByMove);

        #pragma omp parallel num_threads(cloud_.nThreads())
        {
            // A particle's move changes only that particle; what it books as
            // outflow here is discarded and booked below in list order, so
            // that the sums do not depend on the thread count
            List<label> outParticles(nPatches, Zero);
            List<scalar> outNumber(nPatches, Zero);
            List<scalar> outMass(nPatches, Zero);
            coagulationParticle::trackingData threadTd
            (
                cloud_, U, outParticles, outNumber, outMass,
                cloud_.patchInteraction().stick()
            );
            threadTd.setInterpolation(td);

            #pragma omp for schedule(dynamic, 4096)
            for (label i = first; i < nParticles; ++i)
            {
                // The particles lie scattered in memory, in the order they
                // were made: fetch one a few moves ahead into the cache
                const label ahead = i + prefetchDistance;
                if (ahead < nParticles)
                {
                    prefetch
                    (
                        index.particles()[fresh ? cellOrder[ahead] : ahead]
                    );
                }
                const label k = fresh ? cellOrder[i] : i;
                coagulationParticle& p = *index.particles()[k];
                if (fresh)
                {
                    p.stepFraction() = 0;
                    if (walks)
                    {
                        label wallFace = -1;
                        p.dispersal() =
                            walkStep(p, k, dt, walkStream, threadTd, wallFace);
                        if (wallFace >= 0)
                        {
                            // The walk's bridge touched a stick wall
                            p.face() = wallFace;
                            outcome_[k] = depositedByWalk;
                            cells[k] = p.cell();
                            continue;
                        }
                    }
                }
                const label booked = threadTd.nBooked();
                const bool kept = p.move(cloud_, threadTd, dt);
                outcome_[k] =
                    !kept ?
                    (
                        threadTd.nBooked() > booked
                      ? leftByOutflow : droppedByTracking
                    )
                  : threadTd.switchProcessor ? toProcessor
                  : keptByMove;
                cells[k] = p.cell();
            }

            // Counts only: the same whatever the order the threads add them
            #pragma omp critical(frozenFlowMoveCounts)
            {
                for (label i = 0; i < threadTd.nStalled(); ++i)
                {
                    td.bookStalled();
                }
                if (threadTd.nUnhandled())
                {
                    td.bookUnhandled(threadTd.unhandledPatch());
                }
            }
        }

        index.invalidateSort();

        // The deposits of the walk's bridge first, then what the moves did,
        // each in list order, as the path over the linked list books them
        leaving.clear();
        for (label k = first; k < nParticles; ++k)
        {
            if (outcome_[k] == depositedByWalk)
            {
                coagulationParticle& p = *index.particles()[k];
                td.bookOutflow(p.patch(), p);
                cloud_.deleteParticle(p);
            }
        }
        for (label k = first; k < nParticles; ++k)
        {
            if (outcome_[k] == depositedByWalk)
            {
                continue;
            }
            coagulationParticle& p = *index.particles()[k];
            switch (outcome_[k])
            {
                case keptByMove:
                    break;
                case toProcessor:
                    leaving.append(&p);
                    break;
                case leftByOutflow:
                    td.bookOutflow(p.patch(), p);
                    cloud_.deleteParticle(p);
                    break;
                default:
                    cloud_.deleteParticle(p);
            }
        }

        index.compact(outcome_);
        if (!Pstream::parRun())
        {
            break;
        }

        // Processor patches: the leavers go in bulk, what arrives is
        // appended to the list and moves on
        bool sent = false;
        const label nReceived = exchange(leaving, td, sent);
        if (!sent)
        {
            break;
        }
        first = index.particles().size() - nReceived;

        // A move always makes progress, so a particle crosses a processor
        // patch a bounded number of times in a step; rounds without end mean
        // particles handed back and forth: stop rather than hang (every
        // processor takes the same rounds, so all stop here together)
        if (++rounds > maxExchangeRounds)
        {
            FatalErrorInFunction
                << "Particles still crossing processor patches after "
                << maxExchangeRounds << " exchange rounds in one step ("
                << returnReduce(nReceived, sumOp<label>())
                << " handed over in the last round): a particle handed"
                << " back and forth makes no progress" << nl
                << exit(FatalError);
        }
    }
}


Foam::label Foam::coagulation::transportModels::frozenFlow::exchange
(
    const DynamicList<coagulationParticle*>& leaving,
    coagulationParticle::trackingData& td,
    bool& sent
)
{
    // As Cloud::move does it: particles grouped by neighbour, with the
    // neighbour's index of the processor patch they cross
    const polyMesh& mesh = cloud_.pMesh();
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    const globalMeshData& pData = mesh.globalData();
    const labelList& procPatches = pData.processorPatches();
    const labelList& procPatchNeighbours = pData.processorPatchNeighbours();
    const labelList& neighbourProcs = pData[Pstream::myProcNo()];

    labelList neighbourProcIndices(Pstream::nProcs(), -1);
    forAll(neighbourProcs, i)
    {
        neighbourProcIndices[neighbourProcs[i]] = i;
    }

    // One reduction decides whether any processor has a particle to hand
    // over; only then the buffers are exchanged (PstreamBuffers' size
    // exchange is a collective of its own)
    using clock = std::chrono::steady_clock;
    clock::time_point t0 = clock::now();
    sent = returnReduce(!leaving.empty(), orOp<bool>());
    transfers_.waitSeconds +=
        std::chrono::duration<double>(clock::now() - t0).count();
    transfers_.rounds += 1;
    if (!sent)
    {
        return 0;
    }

    List<IDLList<coagulationParticle>> particleTransferLists
    (
        neighbourProcs.size()
    );
    List<DynamicList<label>> patchIndexTransferLists(neighbourProcs.size());

    for (coagulationParticle* pPtr : leaving)
    {
        coagulationParticle& p = *pPtr;
        const label patchi = p.patch();
        const label n = neighbourProcIndices
        [
            refCast<const processorPolyPatch>(pbm[patchi]).neighbProcNo()
        ];
        p.prepareForParallelTransfer();
        particleTransferLists[n].append(cloud_.remove(&p));
        patchIndexTransferLists[n].append(procPatchNeighbours[patchi]);
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(particleTransferLists, i)
    {
        if (particleTransferLists[i].size())
        {
            UOPstream particleStream(neighbourProcs[i], pBufs);
            particleStream
                << patchIndexTransferLists[i]
                << particleTransferLists[i];
        }
    }
    transfers_.particles += leaving.size();
    // Freed here: the particles are in the send buffers
    particleTransferLists.clear();

    labelList allNTrans(Pstream::nProcs());
    t0 = clock::now();
    pBufs.finishedSends(allNTrans);
    transfers_.waitSeconds +=
        std::chrono::duration<double>(clock::now() - t0).count();
    for (const label n : allNTrans)
    {
        transfers_.bytes += n;
    }

    cellParticleIndex& index = cloud_.index();
    label nReceived = 0;
    for (const label neighbProci : neighbourProcs)
    {
        if (allNTrans[neighbProci])
        {
            UIPstream particleStream(neighbProci, pBufs);
            const labelList receivePatchIndex(particleStream);
            IDLList<coagulationParticle> newParticles
            (
                particleStream,
                coagulationParticle::iNew(mesh)
            );

            label pI = 0;
            for (coagulationParticle& newp : newParticles)
            {
                const label patchi = procPatches[receivePatchIndex[pI++]];
                newp.correctAfterParallelTransfer(patchi, td);
                coagulationParticle* pPtr = newParticles.remove(&newp);
                cloud_.addParticle(pPtr);
                index.append(pPtr, pPtr->cell());
                ++nReceived;
            }
        }
    }
    return nReceived;
}


Foam::vector Foam::coagulation::transportModels::frozenFlow::walkStep
(
    const coagulationParticle& p,
    const label k,
    const scalar dt,
    const streamSeeds::purpose walkStream,
    const coagulationParticle::trackingData& td,
    label& wallFace
) const
{
    // The advection over the step with the velocity at the start, for the
    // end point of the bridge near stick walls
    const dispersionModel& dispersion = cloud_.dispersion();
    vector advection(Zero);
    if (dispersion.nearStickWall(p.cell()))
    {
        advection =
            dt*(td.interpolated() ? td.flowVelocity(p) : td.U()[p.cell()]);
    }
    coag::CounterStream stream(cloud_.seeds()(k, walkStream));
    return dispersion.displacement(p, dt, advection, stream, wallFace);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::transportModels::frozenFlow::setFlow
(
    volVectorField& U,
    const scalar t
)
{
    if (series_)
    {
        series_->set(U, t);
        ++flowVersion_;
    }
    else if (cloud_.liveFlow() && liveTimeIndex_ != U.time().timeIndex())
    {
        // The solver has made a step since
        liveTimeIndex_ = U.time().timeIndex();
        ++flowVersion_;
    }
}


void Foam::coagulation::transportModels::frozenFlow::move
(
    const volVectorField& U,
    const scalar dt,
    const streamSeeds::purpose walkStream,
    outflow& out
)
{
    coagulationParticle::trackingData td
    (
        cloud_, U, out.particles, out.number, out.mass,
        cloud_.patchInteraction().stick()
    );
    cloud_.index().invalidateSort();
    if (scheme_ != "cell")
    {
        // The interpolation (its point values) made anew when U changed;
        // cellPoint's sum made on the mesh's tets (meshTets), the same
        // numbers as interpolationCellPoint's
        const bool made = UInterpOf_ == &U && UInterpVersion_ == flowVersion_;
        if (scheme_ == "cellPoint")
        {
            if (!made)
            {
                pointU_ =
                    volPointInterpolation::New(U.mesh()).interpolate(U)
                    ().primitiveField();
            }
            td.setInterpolation
            (
                nullptr, &meshTets::New(cloud_.pMesh()), &pointU_,
                maxCo_, &cellLength_
            );
        }
        else
        {
            if (!made)
            {
                UInterp_ = interpolation<vector>::New(scheme_, U);
            }
            td.setInterpolation
            (
                UInterp_.get(), nullptr, nullptr, maxCo_, &cellLength_
            );
        }
        UInterpOf_ = &U;
        UInterpVersion_ = flowVersion_;
    }

    // The advection with U and the random walk of the dispersion model in
    // one pass over all particles
    if (!cloudMove)
    {
        moveOnThreads(U, td, dt, walkStream);
    }
    else
    {
        // OpenFOAM's Cloud::move over the linked list; a walk's steps are
        // drawn first, in list order, and travel with the particles that
        // change processor; those the bridge took to a stick wall deposit
        cloud_.index().invalidateList();
        if (cloud_.dispersion().active())
        {
            DynamicList<coagulationParticle*> deposited;
            label k = 0;
            for (coagulationParticle& p : cloud_)
            {
                label wallFace = -1;
                p.dispersal() = walkStep(p, k++, dt, walkStream, td, wallFace);
                if (wallFace >= 0)
                {
                    p.face() = wallFace;
                    td.bookOutflow(p.patch(), p);
                    deposited.append(&p);
                }
            }
            for (coagulationParticle* p : deposited)
            {
                cloud_.deleteParticle(*p);
            }
        }
        cloud_.Cloud<coagulationParticle>::move(cloud_, td, dt);
    }

    // A particle that reached a patch type it does not handle was stopped
    // (and is gone from the cloud): stop the run with the patch's name
    if (returnReduce(td.nUnhandled(), sumOp<label>()) > 0)
    {
        const polyBoundaryMesh& patches = cloud_.pMesh().boundaryMesh();
        const label patchi = td.unhandledPatch();
        FatalErrorInFunction
            << "Particles reached patch '"
            << (patchi >= 0 ? patches[patchi].name() : word("?"))
            << "' of type '"
            << (patchi >= 0 ? patches[patchi].type() : word("?"))
            << "' in " << patches.objectPath() << nl
            << "    coagulationFoam handles patch (outflow), wall, symmetry,"
            << " symmetryPlane and empty (rebound), processor, cyclic,"
            << " cyclicAMI and wedge patches" << nl << exit(FatalError);
    }
    out.stalled = td.nStalled();
}


// ************************************************************************* //
