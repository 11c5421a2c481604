// The wires between device ports and plant ports: each tick a WireSet copies its outputs to its
// inputs (scaled, offset, optionally with seeded Gaussian noise). The runner has two sets: plant
// → devices before the nodes step (sensors read the plant at `now`), devices → plant after them
// and before the plant integrates over [now, now + dt].
#pragma once

#include <vector>

#include "sim/scheduler.h"
#include "engine/running/random.h"

namespace scenario {

class WireSet final : public sim::Steppable {
 public:
  struct Link {
    const double* from;
    double* to;
    double scale = 1.0;
    double offset = 0.0;
    double noise = 0.0;
  };
  explicit WireSet(Random* random) : random_(random) {}
  void add(const Link& link) { links_.push_back(link); }
  std::size_t size() const { return links_.size(); }

  void step(sim::Time, sim::Duration) override {
    for (const auto& l : links_) {
      double v = *l.from * l.scale + l.offset;
      if (l.noise > 0) v += l.noise * random_->normal();
      *l.to = v;
    }
  }

 private:
  std::vector<Link> links_;
  Random* random_;
};

}  // namespace scenario
