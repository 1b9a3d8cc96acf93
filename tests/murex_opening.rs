//! The Murex's opening as Galbraith, Prusinkiewicz & Wyvill carve it (§3.3, eqs 14 and 15):
//! the previous whorl subtracted from the inside generating surface, so that the wall between
//! two whorls is single; the aperture, seen head-on, an open and roughly round hole bounded by
//! the previous whorl; and the solids it is carved with, shown apart (figs 10 and 11).

use crate::common;

use common::implicit;
use glam::{DAffine3, DVec3};
use seashells_core::blobtree::blob_tree::Node;
use seashells_core::blobtree::falloff::ISO;
use seashells_core::forms::murex::helix::Instances;
use seashells_core::forms::murex::varix::outward;
use seashells_core::forms::murex::whorl::{Whorl, whorl};
use seashells_core::generator::{BuildError, Generator};
use seashells_core::presets;
use seashells_core::share::link::decode;
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::implicit::{Placement, Shows};

const PRESETS: [&str; 3] = ["murex-cabritii", "murex-pecten", "murex-rd-spines"];

/// A preset's shell without its spines (whose tips a ray may cross), whether the table or the
/// pattern places them, and its instances.
fn body_of(id: &str) -> (ShellSpec, Whorl, Instances) {
    let mut spec = presets::preset(id).expect(id).spec.clone();
    let i = implicit(&mut spec);
    i.varices.placement = Placement::Table;
    i.varices.spines.clear();
    i.canal_spines.spines.clear();
    let rows = spec.growth.rows as usize;
    let instances = Instances::new(implicit(&mut spec), rows);
    let (pattern, seed) = (spec.pattern.clone(), spec.seed);
    let shell = whorl(implicit(&mut spec), &pattern, seed, rows).expect(id);
    (spec, shell, instances)
}

/// The solid stretches (from, to) along `from + t·direction` for t in 0…`length`, sampled
/// every `step`.
fn solid_stretches(
    tree: &Node,
    from: DVec3,
    direction: DVec3,
    length: f64,
    step: f64,
) -> Vec<(f64, f64)> {
    let mut stretches = Vec::new();
    let mut start = None;
    let n = (length / step).ceil() as usize;
    for i in 0..=n {
        let t = i as f64 * step;
        let inside = tree.field(from + direction * t) >= ISO;
        match (inside, start) {
            (true, None) => start = Some(t),
            (false, Some(s)) => {
                stretches.push((s, t));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = start {
        stretches.push((s, length));
    }
    stretches
}

/// The centre of generating surface `k`.
fn centre(instances: &Instances, k: u32) -> DVec3 {
    instances.placement(f64::from(k)).translation
}

#[test]
fn a_ray_from_the_axis_outward_crosses_one_wall_per_whorl() {
    // The centres of the generating surfaces at one azimuth, a whorl apart, lie on a line
    // from the apex (the helico-spiral is self-similar). Along it, from the centre of the
    // whorl two before the last to beyond the last, the shell is one wall between two
    // whorls' hollows: the previous whorl's own, no thicker than it was before the last whorl
    // grew over it (a hollow that stopped at its own inside surface would leave two walls,
    // its own inner one on the previous whorl's outer one), and still there (the hollow did
    // not eat through it).
    for id in PRESETS {
        let (mut spec, shell, instances) = body_of(id);
        let i = implicit(&mut spec);
        let (per_whorl, ahead) = (i.sections * i.surfaces, i.opening.ahead);
        let last = shell.instances - 1;
        for back in [2 * per_whorl / 3, per_whorl / 2, per_whorl / 3] {
            let k = last - back;
            let d = instances.size(f64::from(k));
            let centres = [k - 2 * per_whorl, k - per_whorl, k].map(|k| centre(&instances, k));
            let out = (centres[2] - centres[0]).normalize();
            let length = (centres[2] - centres[0]).length() + 1.5 * d;
            let along = |c: DVec3| (c - centres[0]).dot(out);
            let now = solid_stretches(&shell.tree, centres[0], out, length, d / 400.0);
            // The shell before the last whorl's hollow reached this azimuth.
            let before = shell
                .tree
                .cull(&shell.tree.bounds, k - ahead - 1)
                .expect("grown");
            let then = solid_stretches(&before, centres[0], out, length, d / 400.0);
            for (n, pair) in centres.windows(2).enumerate() {
                let (a, b) = (along(pair[0]), along(pair[1]));
                let between = |s: &[(f64, f64)]| -> Vec<(f64, f64)> {
                    s.iter().copied().filter(|&(x, y)| x > a && y < b).collect()
                };
                let (walls, own) = (between(&now), between(&then));
                assert_eq!(
                    walls.len(),
                    1,
                    "{id} at {k}: walls between whorls {n} and {}: {walls:?} (D = {d})",
                    n + 1
                );
                assert_eq!(
                    own.len(),
                    1,
                    "{id} at {k}: the previous whorl's outer wall {own:?}"
                );
                let (wall, own) = (walls[0].1 - walls[0].0, own[0].1 - own[0].0);
                assert!(
                    wall <= own * 1.02 && wall >= own * 0.5,
                    "{id} at {k}: the wall between whorls {n} and {} is {wall}, the previous whorl's own {own}",
                    n + 1
                );
            }
        }
    }
}

/// How far from the centre of the generating surface placed by `at`, along `direction` (in
/// its coordinates, units of D), the hollow reaches before `tree` is solid; 3 D when it does
/// not end there.
fn hollow_reach(tree: &Node, at: &DAffine3, direction: DVec3) -> f64 {
    let mut r = 0.0;
    while r < 3.0 && tree.field(at.transform_point3(direction * r)) < ISO {
        r += 0.005;
    }
    r
}

#[test]
fn the_aperture_head_on_is_an_open_round_hole_bounded_by_the_previous_whorl() {
    for id in PRESETS {
        let (mut spec, shell, instances) = body_of(id);
        let i = implicit(&mut spec);
        let (wall, ahead) = (i.opening.wall, i.opening.ahead);
        let last = shell.instances - 1;
        let at = instances.placement(f64::from(last));
        // Rays along the aperture's normal (the direction of growth) through its centre region,
        // from a generating surface's size in front of it to a third of one behind, meet nothing.
        for a in (0..360).step_by(30) {
            for r in [0.0, 0.25, 0.5] {
                let across = outward(f64::from(a)) * r;
                for n in 0..=26 {
                    let z = 1.0 - f64::from(n) * 0.05;
                    let p = at.transform_point3(across + DVec3::Z * z);
                    let f = shell.tree.field(p);
                    assert!(
                        f < ISO,
                        "{id}: a head-on ray {r} D out at {a}° meets the shell {z} D before the aperture ({f})"
                    );
                }
            }
        }
        // Roughly round: away from the canal (which runs on as an open groove between 180°
        // and 270°, towards the axis and down), the hole's radius varies by less than a third.
        let radii: Vec<f64> = (0..360)
            .step_by(15)
            .filter(|a| !(181..270).contains(a))
            .map(|a| hollow_reach(&shell.tree, &at, outward(f64::from(a))))
            .collect();
        let (least, most) = radii
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(l, m), &r| (l.min(r), m.max(r)));
        assert!(
            least > 0.5 && most / least < 4.0 / 3.0,
            "{id}: the aperture's radii {radii:.2?}"
        );
        // Bounded by the previous whorl: towards the previous whorl's centre (up and in),
        // the rim lies on the shell that was there before the growing edge came.
        let per_whorl = i.sections * i.surfaces;
        let previous = at
            .inverse()
            .transform_point3(centre(&instances, last - per_whorl));
        let towards = DVec3::new(previous.x, previous.y, 0.0).normalize();
        let rim = hollow_reach(&shell.tree, &at, towards);
        let before = shell
            .tree
            .cull(&shell.tree.bounds, last - wall - ahead - 1)
            .expect("grown");
        let behind = at.transform_point3(towards * (rim + 0.05));
        assert!(
            before.field(behind) >= ISO,
            "{id}: the aperture's rim towards the previous whorl ({towards:.2?}, {rim} D out) is not on it"
        );
    }
}

/// The grown tree of `link`'s shell (every instance placed).
fn grown_tree(link: &str) -> Node {
    let decoded = decode(link);
    assert!(
        decoded.problems.is_empty(),
        "{link}: {:?}",
        decoded.problems
    );
    let mut spec = decoded.spec;
    let rows = spec.growth.rows as usize;
    let (pattern, seed) = (spec.pattern.clone(), spec.seed);
    let built = whorl(implicit(&mut spec), &pattern, seed, rows).expect(link);
    (built.tree)
        .cull(&built.tree.bounds, built.instances - 1)
        .expect("a solid")
}

#[test]
fn the_solids_of_eq_14_are_shown_apart_as_in_figs_10_and_11() {
    // Fig 10: the inside whorl B_inside, and B_opening = B_inside − B_{w−1}, what is carved;
    // fig 11 (left): the shell carved by eq 14 alone, without eq 15's inside wall.
    let link = |extra: &str| format!("v=1&preset=murex-cabritii{extra}");
    let inside = grown_tree(&link("&form.opening.shows=inside"));
    let opening = grown_tree(&link("&form.opening.shows=opening"));
    let carved = grown_tree(&link("&form.opening.wall=0"));
    let b = inside.bounds;
    let (mut in_inside, mut in_opening) = (0, 0);
    let n = 28;
    for (x, y, z) in (0..n).flat_map(|x| (0..n).flat_map(move |y| (0..n).map(move |z| (x, y, z)))) {
        let f = DVec3::new(x as f64, y as f64, z as f64) / f64::from(n - 1);
        let p = b.min + (b.max - b.min) * f;
        let (i, o) = (inside.field(p) > ISO, opening.field(p) > ISO);
        in_inside += usize::from(i);
        in_opening += usize::from(o);
        assert!(!o || i, "{p}: in B_opening, not in B_inside");
        assert!(
            !o || carved.field(p) <= ISO,
            "{p}: carved out, still in the shell"
        );
    }
    assert!(
        in_opening > 0 && in_opening < in_inside,
        "the previous whorl is taken out of the inside whorl: {in_opening} of {in_inside} samples"
    );
}

#[test]
fn on_a_tile_s_coarse_grid_the_inside_whorl_grows_and_an_empty_opening_says_why() {
    // A map's tile of the Murex is polygonized on 25 voxels, too coarse to show any whorl's
    // hollow with its wall: the shell is solid, nothing is carved. Drawn alone, the inside
    // whorl has no wall to keep and still grows; the opening, what is carved, is nothing, and
    // says so.
    let link = "v=1&preset=murex-cabritii&form.resolution=25";
    let decoded = decode(&format!("{link}&form.opening.shows=inside"));
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    let mut grown = Generator::new(&decoded.spec).expect("the inside whorl");
    grown.finish();
    common::assert_closed_and_outward(&grown.snapshot(), "the inside whorl at 25 voxels");
    let decoded = decode(&format!("{link}&form.opening.shows=opening"));
    let Err(BuildError::Shape(e)) = Generator::new(&decoded.spec) else {
        panic!("an opening of nothing is refused");
    };
    assert_eq!(e.key, "form.opening.shows");
    assert!(e.message.contains("25 voxels"), "{}", e.message);
}

#[test]
fn a_solid_shell_has_no_opening_to_show() {
    let decoded = decode("v=1&preset=implicit-whorl&form.opening.shows=opening");
    assert!(
        decoded
            .problems
            .iter()
            .any(|p| p.key == "form.opening.shows"),
        "{:?}",
        decoded.problems
    );
    assert_eq!(
        implicit(&mut decoded.spec.clone()).opening.shows,
        Shows::Shell
    );
}

#[test]
fn the_hollow_reaches_four_whorls_in_from_the_aperture_at_every_resolution() {
    // Its wall is never thinner than 0.7/224 of the shell (`opening::THINNEST_WALL`), which a
    // grid of 112 voxels shows with its voxels halved there: before, at 0.7/112, it stopped
    // 2.4 whorls in (2.2 in pecten). Every grid of 112 voxels or more builds this tree.
    for id in PRESETS {
        let (mut spec, shell, instances) = body_of(id);
        let i = implicit(&mut spec);
        let per_whorl = i.sections * i.surfaces;
        let last = shell.instances - 1;
        let solid: Vec<u32> = (last - 4 * per_whorl..=last)
            .filter(|&k| shell.tree.field(centre(&instances, k)) >= ISO)
            .collect();
        assert!(
            solid.is_empty(),
            "{id}: the centres of generating surfaces {solid:?} of {last} are solid"
        );
    }
}
