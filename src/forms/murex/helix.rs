//! The helico-spiral of Galbraith, Prusinkiewicz & Wyvill (§3.1) and the instances of the
//! generating surface placed along it by P(B, θ) (eq 8), one per growth step.
//!
//! The paper's equations 1–3, as we read them: R(θ) = R₀ λ^(θ/2π); H(θ) = R(θ) cot β; and, for
//! circles of consecutive whorls that touch, D(θ) = R(θ)(λ − 1) / ((λ + 1) sin β), which gives
//! the paper's D = 0.341 R for β = 22.5°, λ = 1.3. The paper's y axis is our z: as for all our
//! shells, the apex points towards −z and growth goes towards +z (the display turns it apex up).

use crate::spec::form::implicit::{HelixSpec, ImplicitSpec};
use crate::spec::handedness::Handedness;
use glam::{DAffine3, DMat3, DVec3};
use std::f64::consts::TAU;

/// The helico-spiral of eqs 1–3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Helix {
    r0: f64,
    lambda: f64,
    cot_beta: f64,
    /// D / R (eq 3).
    size: f64,
    handedness: Handedness,
}

impl Helix {
    pub fn new(spec: &HelixSpec) -> Self {
        let beta = spec.beta.to_radians();
        Self {
            r0: spec.r0,
            lambda: spec.lambda,
            cot_beta: libm::cos(beta) / libm::sin(beta),
            size: (spec.lambda - 1.0) / ((spec.lambda + 1.0) * libm::sin(beta)),
            handedness: spec.handedness,
        }
    }

    /// R(θ), eq 1.
    pub fn radius(&self, theta: f64) -> f64 {
        self.r0 * libm::pow(self.lambda, theta / TAU)
    }

    /// H(θ), eq 2.
    pub fn height(&self, theta: f64) -> f64 {
        self.radius(theta) * self.cot_beta
    }

    /// D(θ), eq 3.
    pub fn size(&self, theta: f64) -> f64 {
        self.radius(theta) * self.size
    }

    /// The growth direction at θ: the w axis of the generating surface.
    pub fn growth_direction(&self, theta: f64) -> DVec3 {
        self.handedness
            .mirror(DVec3::new(-libm::sin(theta), libm::cos(theta), 0.0))
    }

    /// P(·, θ) of eq 8: scale by D(θ), then carry the generating surface's u (towards the
    /// axis), v (along the axis, towards the apex: −z) and w (along the growth) to the point
    /// (R(θ), H(θ)) of the half plane at angle θ about the axis.
    pub fn placement(&self, theta: f64) -> DAffine3 {
        let (s, c) = (libm::sin(theta), libm::cos(theta));
        let d = self.size(theta);
        let r = self.radius(theta);
        let u = self.handedness.mirror(DVec3::new(-c, -s, 0.0));
        let w = self.growth_direction(theta);
        DAffine3 {
            matrix3: DMat3::from_cols(u * d, DVec3::NEG_Z * d, w * d),
            translation: self
                .handedness
                .mirror(DVec3::new(r * c, r * s, self.height(theta))),
        }
    }
}

/// The instances of the generating surface along the helico-spiral: one per growth step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Instances {
    helix: Helix,
    /// Radians between consecutive instances.
    step: f64,
    /// Instances per whorl.
    per_whorl: u32,
    /// Pattern rows between consecutive instances.
    time_step: f64,
    /// Instances in the whole shell.
    pub count: u32,
}

impl Instances {
    pub fn new(spec: &ImplicitSpec, rows: usize) -> Self {
        let per_whorl = spec.sections * spec.surfaces;
        let count = spec.whorls * per_whorl;
        Self {
            helix: Helix::new(&spec.spiral),
            step: spec.whorl_angle.to_radians() / f64::from(per_whorl),
            per_whorl,
            time_step: (rows.max(2) - 1) as f64 / f64::from((count - 1).max(1)),
            count,
        }
    }

    /// P(·, θ) of eq 8 for instance `k`, fractions allowed.
    pub fn placement(&self, k: f64) -> DAffine3 {
        self.helix.placement(k * self.step)
    }

    /// The direction of growth at instance `k`.
    pub fn growth_direction(&self, k: f64) -> DVec3 {
        self.helix.growth_direction(k * self.step)
    }

    /// D(θ) at instance `k`.
    pub fn size(&self, k: f64) -> f64 {
        self.helix.size(k * self.step)
    }

    /// The whorl instance `k` lies in, counted from 0 at the apex, with its fraction.
    pub fn whorl(&self, k: f64) -> f64 {
        k / f64::from(self.per_whorl)
    }

    /// The pattern row instance `k` grows on.
    pub fn time(&self, k: f64) -> f64 {
        k * self.time_step
    }
}
