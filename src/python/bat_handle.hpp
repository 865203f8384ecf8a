#pragma once
// A bat as Python holds it: the sliced bat, its mass properties and the modal bases solved so far,
// one per (theory, ModeRequest), so that impacts on the same bat solve each basis once. Safe to
// use from several threads at once (impacts release the GIL).
#include <map>
#include <memory>
#include <mutex>
#include <tuple>

#include <optional>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/error_estimates.hpp"

namespace sweetspot::python {

class BatHandle {
 public:
  // The bat, the design it was built from (what certification and a designer's numbers read) and
  // the texts that give the design (empty for a bat of knots given in Python): what a result
  // stores so that the bat can be told apart and rebuilt.
  BatHandle(Bat bat, BatDesign design, BatSource source = {})
      : bat_(std::move(bat)), design_(std::move(design)), source_(std::move(source)), mass_(mass_properties(bat_)) {}

  const Bat& bat() const { return bat_; }
  const BatDesign& design() const { return design_; }
  const BatSource& source() const { return source_; }
  const MassProperties& mass() const { return mass_; }

  // The basis of this request, solved on first use (outside the lock: two threads asking the same
  // new basis may both solve it, and the first stored is kept; the solve is deterministic).
  std::shared_ptr<const ModalBasis> basis(BeamTheory theory, ModeRequest request) {
    const Key key{static_cast<int>(theory), request.vibrational, request.below_omega};
    {
      const std::lock_guard lock(mutex_);
      if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    }
    auto solved = std::make_shared<const ModalBasis>(compute_modes(bat_, theory, request));
    const std::lock_guard lock(mutex_);
    return cache_.emplace(key, std::move(solved)).first->second;
  }

  // The same design at slicing_refinement times the slices (error_estimates.hpp), made on first
  // use and kept: its bases are cached as this bat's are. nullptr where it cannot be refined.
  BatHandle* finer(BeamTheory theory) {
    if (!can_refine(bat_.slices(), theory)) return nullptr;
    const std::lock_guard lock(mutex_);
    if (!finer_)
      finer_ = std::make_unique<BatHandle>(bat_with_slices(design_, slicing_refinement * bat_.slices()), design_);
    return finer_.get();
  }

 private:
  using Key = std::tuple<int, int, double>;
  Bat bat_;
  BatDesign design_;
  BatSource source_;
  MassProperties mass_;
  std::mutex mutex_;
  std::map<Key, std::shared_ptr<const ModalBasis>> cache_;
  std::unique_ptr<BatHandle> finer_;
};

}  // namespace sweetspot::python
