#pragma once
// `coatfft run` on the ranks of a communicator (docs/scale.md): a [contact] or known-[pressure]
// scene on row slabs (distributed/slab.hpp), by the distributed periodic or free-surface operator
// and the distributed contact solver, each rank holding its rows of every field (a height map's
// or a pressure file's rows read by each rank, io/npy_slab.hpp; a closed-form load sampled by
// rows). summary.json's object is the serial run's, the same on every rank, with
// "ranks". What does not run distributed yet is refused by name before any work. Built with
// COATFFT_MPI.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/types.hpp"
#include "distributed/communicator.hpp"
#include "distributed/slab.hpp"
#include "scene/scene_run.hpp"

namespace coatfft::scene {

/// What a distributed run computes: this rank's rows of the fields, and summary.json's object.
struct DistributedSceneRun {
  Slab slab;
  Field pressure, uz, gap;  ///< (nx, slab.rows): [Pa], [m], [m]
  nlohmann::json summary;   ///< the same on every rank
  RunStatus status = RunStatus::ok;
};

/// Throws InvalidArgument naming the first part of `scene` that does not run distributed yet:
/// "auto", a free boundary's method other than dcfft or frf-split, a measured topography, a sweep,
/// friction, [shear], [stress], ux/uy (docs/scale.md lists them).
void check_distributable(const Scene& scene);

/// prepare_scene for the ranks of `comm` (the same on each): the scene read with a height map's
/// values left unread, check_distributable, and the memory a rank needs (the serial estimate over
/// the ranks, plus the slab transforms' overhead, docs/scale.md) checked against --max-memory
/// (per rank) or the available memory shared by the ranks of this machine. What each rank checks
/// alone is agreed (distributed/detail/agreed_refusal.hpp): a refusal on any rank is thrown on
/// every rank, naming it, as are scene files (or --repeat) that differ between the ranks, naming
/// both. Collective.
PreparedScene prepare_distributed_scene(const Communicator& comm,
                                        const std::filesystem::path& scene_file,
                                        const SceneRunOptions& options);

/// compute_scene on the ranks of `comm`: the contact solve (without the nested start,
/// docs/scale.md) or the known load's displacement and reports, and the timed applications.
/// Collective.
DistributedSceneRun compute_distributed_scene(const Communicator& comm,
                                              const PreparedScene& prepared,
                                              const SceneRunOptions& options);

}  // namespace coatfft::scene
