// mutants2d.h -- deliberately broken 2D outputs, to show that the chapter-3 rows can fail.
//
// Each mutant changes the engine's output (a GrassfireResult, a PotentialResidue) or the
// axis a builder returned, after the engine ran and before any row reads it; references
// (the oracle, rate pruning, peeling, the shape's rings, the definition-level validation
// of a union of disks) are never touched, and the kernel's hot paths are not either. New
// times are made exactly, as records of the result's BurnTimes (an advance along an edge).
//  - leaf-late: one leaf ignites one edge length late (its EDF and the fire it sends).
//  - junction-first / junction-last: one junction burns at its first arrival, or at the
//    arrival along the edge it should burn into (the last one), instead of leaving one edge.
//  - edf-shift-edge: the fire sent into one edge starts one edge length late.
//  - core-burns: one node of the 2-core gets the finite EDF R.
//  - ema-moved: the EMA point of one tree component moves to a neighbouring node.
//  - ema-topology: a second EMA point for one tree component, or one edge dropped from the
//    EMA of a component with cycles.
//  - axis-edge-dropped: the axis a builder returned loses its last edge.
//  - pr-dip / pr-junction-dip / pr-extra-maximum: PR halved at a degree-2 node; the largest
//    limit at a junction halved; a leaf raised above the PR maximum.
#pragma once

#include "burn2/extended_grassfire.h"
#include "burn2/potential_residue.h"
#include "check_registry.h"

namespace grassfire::checks {

MutantList grassfire_mutants();  // those on a GrassfireResult and axis-edge-dropped
MutantList residue_mutants();    // pr-*

void mutate_grassfire(const CheckContext& ctx, const MedialGraph& g, GrassfireResult& r);
void mutate_residue(const CheckContext& ctx, const MedialGraph& g, PotentialResidue& pr);
// g without its last edge under axis-edge-dropped, else g itself (copied).
MedialGraph mutate_axis(const CheckContext& ctx, const MedialGraph& g);

}  // namespace grassfire::checks
