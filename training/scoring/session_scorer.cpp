#include "training/scoring/session_scorer.hpp"

namespace needle::training {

SessionScorer::SessionScorer(const Task& task)
    : task_(task), progress_(task), layers_(task), patient_(task), syringe_(task) {
  steps_.reserve(task.steps.size());
  for (const Step& step : task.steps) steps_.emplace_back(task, step);
}

ContactEvents SessionScorer::contact_events(const haptics::ToolSnapshot& s) {
  using haptics::ContactState;
  ContactEvents e;
  const double t = s.time_s;
  const bool was_tissue = started_ && contact_ == ContactState::kTissue;
  const bool was_rigid = started_ && contact_ == ContactState::kRigidSurface;
  if (s.contact == ContactState::kTissue && !was_tissue) {
    if (withdrawal_pending_)
      withdrawal_pending_ = false;  // chatter: the same insertion
    else
      e.reinsertion = inserted_;
    inserted_ = true;
  }
  if (was_tissue && s.contact != ContactState::kTissue) {
    withdrawal_pending_ = true;
    tissue_left_s_ = t;
  }
  if (withdrawal_pending_ && t - tissue_left_s_ >= kContactDebounce_s) {
    withdrawal_pending_ = false;
    e.withdrawal = true;
  }
  if (s.contact == ContactState::kRigidSurface && !was_rigid) {
    e.rigid_entry = !rigid_seen_ || t - rigid_left_s_ >= kContactDebounce_s;
    rigid_seen_ = true;
  }
  if (was_rigid && s.contact != ContactState::kRigidSurface) rigid_left_s_ = t;
  e.fault = s.fault != 0 && fault_ == 0;
  if (s.contact != ContactState::kTissue)
    entry_.reset();
  else if (!entry_)
    entry_ = vec3(s.needle_tip_m);
  e.entry = entry_ ? &*entry_ : nullptr;
  started_ = true;
  contact_ = s.contact;
  fault_ = s.fault;
  return e;
}

void SessionScorer::feed(const haptics::TickSample& sample) {
  if (progress_.finished()) return;
  const haptics::ToolSnapshot& s = sample.state;
  ContactEvents events = contact_events(s);
  events.layers = &layers_.feed(s, events.entry);
  patient_.feed(s, events.entry);
  if (task_.syringe) events.syringe = &syringe_.feed(s);
  const size_t step = progress_.current_step();
  steps_[step].add(s, events);
  progress_.feed(s);
  // The state that ends a step also starts the next: its path begins where the last one ended.
  if (!progress_.finished() && progress_.current_step() != step)
    steps_[progress_.current_step()].add(s, ContactEvents{.entry = events.entry});
}

SessionResult SessionScorer::result() const {
  SessionResult r;
  for (size_t i = 0; i < steps_.size(); ++i)
    r.steps.push_back({task_.steps[i].id, progress_.records()[i], steps_[i].result(),
                       step_failure_reason(task_, progress_.records()[i])});
  r.overall = combine_metrics(r.steps);
  patient_.write(r.overall);
  r.score = score_session(task_.scoring, r.steps, r.overall);
  r.finished = progress_.finished();
  for (const PunctureRecord& p : layers_.punctures())
    r.punctures.push_back({task_.layers[size_t(p.layer)].name, p.t_s, p.depth_m, p.peak_force_N});
  return r;
}

}  // namespace needle::training
