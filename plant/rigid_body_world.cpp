#include "plant/rigid_body_world.h"

#include <ode/ode.h>

#include <cmath>
#include <numbers>

#include "sim/tick_profile.h"

namespace plant {
namespace {

// ODE keeps library-wide state (its allocator hooks, collision tables): initialise it once per
// process and never close it, since several plants may live at once.
void ensure_ode_initialised() {
  static const bool initialised = [] {
    dInitODE2(0);
    return true;
  }();
  (void)initialised;
}

// Where a slider is put back when ODE lets it pass an end stop within a step: a hair inside the
// stop, so ODE's limit is active (position <= stop) at the next step and holds the body there.
constexpr double kStopInset = 1e-12;

// A friction motor counts as saturated (the body slides on) when the force needed to stop the body
// within the step exceeds its limit by this fraction, and as holding when it stays below it by
// this fraction; the cases between are left to ODE's LCP.
constexpr double kSaturationMargin = 1e-9;

}  // namespace

struct RigidBodyWorld::Dof {
  dBodyID body = nullptr;
  dJointID joint = nullptr;
  dJointFeedback feedback{};
  bool slider = true;
  double lower = 0.0;
  double upper = 0.0;
  double mass = 1.0;
  double position = 0.0;   // slider: clamped to the stops; hinge: unwrapped angle
  double joint_position = 0.0;  // slider: the joint's position as ODE measures it (a hair past a stop)
  double raw_angle = 0.0;  // hinge: ODE's wrapped angle at the last step
  double velocity = 0.0;
  double friction_loss = 0.0;
  double impact_loss = 0.0;
  bool enabled = true;       // the ODE body takes part in dWorldStep
  bool closed_form = false;  // this step: integrated in closed form, not by ODE
  bool resting = false;      // closed form: held at rest by its friction motor
  double motor_force = 0.0;  // closed form: the saturated friction motor's force on the body
  // Closed-form steps leave ODE's copy of the body alone: its position, orientation and velocity
  // are brought up to date only when ODE steps the body again (hand_to_ode()).
  bool ode_current = true;
  double pending_turn = 0.0;  // hinge: rotation since ODE's copy was last current
};

RigidBodyWorld::RigidBodyWorld() {
  ensure_ode_initialised();
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0, 0, 0);  // loads are explicit forces; orientation is the scenario's business
}

RigidBodyWorld::~RigidBodyWorld() { dWorldDestroy(world_); }

RigidBodyWorld::Dof& RigidBodyWorld::at(DofId dof) const { return *dofs_[static_cast<std::size_t>(dof.index)]; }

DofId RigidBodyWorld::add_slider(double lower, double upper, double initial_position) {
  auto d = std::make_unique<Dof>();
  d->slider = true;
  d->body = dBodyCreate(world_);
  d->joint = dJointCreateSlider(world_, nullptr);
  dJointAttach(d->joint, d->body, nullptr);
  dJointSetSliderAxis(d->joint, 1, 0, 0);  // zero position = where the body is now (origin)
  dJointSetSliderParam(d->joint, dParamVel, 0);
  dJointSetSliderParam(d->joint, dParamFMax, 0);
  dJointSetSliderParam(d->joint, dParamCFM, 0);     // a held body stays exactly at rest
  dJointSetSliderParam(d->joint, dParamBounce, 0);  // inelastic stops
  dJointSetSliderParam(d->joint, dParamStopERP, 0);  // penetration is projected out in step()
  dJointSetFeedback(d->joint, &d->feedback);
  dBodySetPosition(d->body, initial_position, 0, 0);
  d->position = d->joint_position = initial_position;
  dofs_.push_back(std::move(d));
  const DofId id{size() - 1};
  set_limits(id, lower, upper);
  set_mass(id, 1.0);
  return id;
}

DofId RigidBodyWorld::add_hinge(double initial_angle) {
  auto d = std::make_unique<Dof>();
  d->slider = false;
  d->body = dBodyCreate(world_);
  d->joint = dJointCreateHinge(world_, nullptr);
  dJointAttach(d->joint, d->body, nullptr);
  dJointSetHingeAnchor(d->joint, 0, 0, 0);
  dJointSetHingeAxis(d->joint, 0, 0, 1);  // zero angle = the body's orientation now
  dJointSetHingeParam(d->joint, dParamVel, 0);
  dJointSetHingeParam(d->joint, dParamFMax, 0);
  dJointSetHingeParam(d->joint, dParamCFM, 0);
  dJointSetFeedback(d->joint, &d->feedback);
  // Rotate exactly about the hinge axis each step (no small-angle quaternion update error).
  dBodySetFiniteRotationMode(d->body, 1);
  dBodySetFiniteRotationAxis(d->body, 0, 0, 1);
  dQuaternion q;
  dQFromAxisAndAngle(q, 0, 0, 1, initial_angle);
  dBodySetQuaternion(d->body, q);
  d->position = initial_angle;
  d->raw_angle = dJointGetHingeAngle(d->joint);
  dofs_.push_back(std::move(d));
  const DofId id{size() - 1};
  set_mass(id, 1.0);
  return id;
}

void RigidBodyWorld::set_mass(DofId dof, double mass) {
  Dof& d = at(dof);
  d.mass = mass;
  dMass m;
  dMassSetZero(&m);
  if (d.slider) {
    // Rotation is locked by the joint; any positive inertia will do.
    const double i = 0.01 * mass;
    dMassSetParameters(&m, mass, 0, 0, 0, i, i, i, 0, 0, 0);
  } else {
    // Translation is locked by the joint; the inertia about the axis is what counts.
    dMassSetParameters(&m, 1.0, 0, 0, 0, mass, mass, mass, 0, 0, 0);
  }
  dBodySetMass(d.body, &m);
}

void RigidBodyWorld::set_limits(DofId dof, double lower, double upper) {
  Dof& d = at(dof);
  d.lower = lower;
  d.upper = upper;
  // ODE wants lo <= hi at every moment: widen first, then narrow.
  dJointSetSliderParam(d.joint, dParamLoStop, -dInfinity);
  dJointSetSliderParam(d.joint, dParamHiStop, upper);
  dJointSetSliderParam(d.joint, dParamLoStop, lower);
}

bool RigidBodyWorld::is_slider(DofId dof) const { return at(dof).slider; }
double RigidBodyWorld::lower(DofId dof) const { return at(dof).lower; }
double RigidBodyWorld::upper(DofId dof) const { return at(dof).upper; }
double RigidBodyWorld::position(DofId dof) const { return at(dof).position; }
double RigidBodyWorld::velocity(DofId dof) const { return at(dof).velocity; }
double RigidBodyWorld::friction_loss(DofId dof) const { return at(dof).friction_loss; }
double RigidBodyWorld::impact_loss(DofId dof) const { return at(dof).impact_loss; }

// ODE sizes its step memory at the first dWorldStep from the bodies and joints taking part (their
// largest row counts) and grows it when more take part. Bodies join ODE's steps only while a
// constraint acts, so that first step could come at any tick: one step of every body now, at rest
// and without force (nothing moves), sizes it for all of them before the first tick.
void RigidBodyWorld::reserve_step_memory() {
  for (auto& d : dofs_) {
    hand_to_ode(*d);
    if (!d->enabled) {
      dBodyEnable(d->body);
      d->enabled = true;
    }
  }
  if (!dofs_.empty()) dWorldStep(world_, 1e-9);
}

void RigidBodyWorld::hand_to_ode(Dof& d) {
  if (d.ode_current) return;
  if (d.slider) {
    const dReal* p = dBodyGetPosition(d.body);
    dBodySetPosition(d.body, p[0] + (d.joint_position - dJointGetSliderPosition(d.joint)), p[1], p[2]);
    const dReal* lv = dBodyGetLinearVel(d.body);
    dBodySetLinearVel(d.body, d.velocity, lv[1], lv[2]);
  } else {
    dQuaternion dq, q;
    dQFromAxisAndAngle(dq, 0, 0, 1, d.pending_turn);
    dQMultiply0(q, dq, dBodyGetQuaternion(d.body));
    dBodySetQuaternion(d.body, q);
    d.pending_turn = 0.0;
    d.raw_angle = dJointGetHingeAngle(d.joint);
    dBodySetAngularVel(d.body, 0, 0, d.velocity);
  }
  d.ode_current = true;
}

void RigidBodyWorld::step(double h, std::span<const double> force, std::span<const double> friction_limit) {
  const sim::TickProbe probe(sim::TickPart::Ode);
  // Which bodies ODE steps. Clear of its stops, a body's only constraint in a step is its
  // friction motor, one row decoupled from the joint's others, whose LCP has a closed-form
  // solution: the motor force that would bring the body to rest within the step, clamped to the
  // friction limit. Held (not clamped): the body stays at rest, v1 = 0 - a resting body, which ODE
  // need not step. Clamped: the body slides on under the constant force -limit sign(v), and ODE's
  // step reduces to v1 = v0 + h (F + lambda) / m. On a stop, the limit row joins in: when the
  // force pushes the body into the stop, or the motor can hold it, the body stays where it is
  // (v1 = 0, the stop and the motor share the force, neither does work) - a body at rest on its
  // stop, which ODE need not step either. All three are done here; cases within a margin of the
  // limit, and a body leaving its stop, are ODE's. Bodies not stepped by ODE are disabled for that
  // step so that it skips their islands, and their ODE copy is brought up to date only when ODE
  // steps them next (docs/plant.md, "Which bodies ODE steps").
  bool any_in_ode = false;
  for (std::size_t i = 0; i < dofs_.size(); ++i) {
    Dof& d = *dofs_[i];
    const double limit = friction_limit[i];
    const double stop_force = -d.mass * d.velocity / h - force[i];
    // ODE's own test of a slider's stops (at the start of the step), on the joint position ODE
    // would measure.
    const bool on_lower = d.slider && d.joint_position <= d.lower;
    const bool on_upper = d.slider && !on_lower && d.joint_position >= d.upper;
    const double below = limit * (1.0 - kSaturationMargin);
    if (on_lower || on_upper) {
      // Held on the stop: lambda pushes into it (the stop can take any part of it), or the motor
      // can supply it.
      d.closed_form = on_lower ? stop_force > -below : stop_force < below;
      d.resting = true;
      d.motor_force = 0.0;
    } else {
      const bool slides = std::abs(stop_force) > limit * (1.0 + kSaturationMargin);
      const bool holds = std::abs(stop_force) < below;
      d.closed_form = slides || holds;
      d.resting = holds;
      d.motor_force = holds ? stop_force : stop_force > 0.0 ? limit : -limit;
    }
    if (d.closed_form) {
      if (d.enabled) {
        dBodyDisable(d.body);
        d.enabled = false;
      }
      continue;
    }
    hand_to_ode(d);
    if (!d.enabled) {
      dBodyEnable(d.body);
      d.enabled = true;
    }
    any_in_ode = true;
    if (d.slider) {
      dJointSetSliderParam(d.joint, dParamFMax, limit);
      dBodyAddForce(d.body, force[i], 0, 0);
    } else {
      dJointSetHingeParam(d.joint, dParamFMax, limit);
      dBodyAddTorque(d.body, 0, 0, force[i]);
    }
  }
  if (any_in_ode) {
    dWorldStep(world_, h);
    ++ode_steps_;
  }
  for (std::size_t i = 0; i < dofs_.size(); ++i) {
    Dof& d = *dofs_[i];
    d.impact_loss = 0.0;
    const double v0 = d.velocity;
    if (d.slider) {
      double x;
      if (d.closed_form) {
        d.velocity = d.resting ? 0.0 : v0 + h * (force[i] + d.motor_force) / d.mass;
        // Trapezoidal position, as below for ODE's steps.
        x = d.joint_position + 0.5 * h * (v0 + d.velocity);
        d.friction_loss = -d.motor_force * d.velocity * h;
        d.ode_current = false;
      } else {
        d.velocity = dJointGetSliderPositionRate(d.joint);
        // ODE advances positions with the end-of-step velocity (x += h v1, first order); move the
        // body back by h/2 (v1 - v0) so the position follows the trapezoidal rule, x += h (v0+v1)/2,
        // matching the second-order velocities of the circuit solver.
        const dReal* p = dBodyGetPosition(d.body);
        dBodySetPosition(d.body, p[0] - 0.5 * h * (d.velocity - v0), p[1], p[2]);
        x = dJointGetSliderPosition(d.joint);
        // Joint force on the body along the axis (motor + stop) times the step's displacement.
        d.friction_loss = -d.feedback.f1[0] * d.velocity * h;
      }
      // ODE engages a stop only from the step after the body reached it: project the overshoot
      // out and end the motion into the stop (an inelastic impact).
      const bool past_lower = x < d.lower, past_upper = x > d.upper;
      if (past_lower || past_upper) {
        const double stop = past_lower ? d.lower - kStopInset : d.upper + kStopInset;
        if (!d.closed_form) {
          const dReal* p = dBodyGetPosition(d.body);
          dBodySetPosition(d.body, p[0] + (stop - x), p[1], p[2]);
        }
        if ((past_lower && d.velocity < 0.0) || (past_upper && d.velocity > 0.0)) {
          d.impact_loss = 0.5 * d.mass * d.velocity * d.velocity;
          d.velocity = 0.0;
          if (!d.closed_form) dBodySetLinearVel(d.body, 0, 0, 0);
        }
        x = stop;
      }
      d.joint_position = x;
      d.position = x < d.lower ? d.lower : x > d.upper ? d.upper : x;  // (fmin/fmax are library calls)
    } else {
      double turn;  // the step's rotation about the axis, trapezoidal as for sliders
      if (d.closed_form) {
        d.velocity = d.resting ? 0.0 : v0 + h * (force[i] + d.motor_force) / d.mass;
        turn = 0.5 * h * (v0 + d.velocity);
        d.friction_loss = -d.motor_force * d.velocity * h;
        d.pending_turn += turn;
        d.position += turn;
        d.ode_current = false;
        continue;
      }
      d.velocity = dJointGetHingeAngleRate(d.joint);
      // ODE turned the body by h w1: turn back by h/2 (w1 - w0) about the axis.
      turn = -0.5 * h * (d.velocity - v0);
      d.friction_loss = -d.feedback.t1[2] * d.velocity * h;
      dQuaternion dq, q;
      dQFromAxisAndAngle(dq, 0, 0, 1, turn);
      dQMultiply0(q, dq, dBodyGetQuaternion(d.body));
      dBodySetQuaternion(d.body, q);
      const double raw = dJointGetHingeAngle(d.joint);
      d.position += std::remainder(raw - d.raw_angle, 2.0 * std::numbers::pi);
      d.raw_angle = raw;
    }
  }
}

}  // namespace plant
