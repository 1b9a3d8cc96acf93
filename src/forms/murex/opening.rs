//! The opening (Galbraith, Prusinkiewicz & Wyvill §3.3, eqs 14 and 15): the hollow inside of
//! the shell, carved as the paper carves it and open at every stage of growth.
//!
//! B_opening is built "using the same method described for the main body whorl": an inside
//! generating surface slightly smaller than the body's (a point primitive and the slender
//! cones of the inner canal), with cones that extend its inner edge to the edge of the
//! previous whorl, placed along the same helico-spiral. The previous whorl B_{w−1} is
//! subtracted from it, B_opening = B_inside − B_{w−1}, and B_opening from the shell (eq 14):
//! the hollow then reaches the previous whorl and stops at its surface, so the wall between
//! two whorls is the previous whorl's own, single, and the previous whorl stays intact. The
//! aperture that leaves is not round: the previous whorl bulges into it where the extension
//! carved through the body's inner wall. So, as the paper does after observing *Murex
//! troschei*, an inside wall is modelled separately and added back (eq 15), B_murex =
//! (B_shell − B_opening) ∪ B_inside_wall: over the last generating surfaces at the growing
//! edge, the body's own inner wall (its generating surface less the inside one without the
//! extension), so that the opening is roughly round. It lives only at the growing edge: a
//! growth step that moves the edge on takes it away behind.
//!
//! The paper carves the finished shell once. Ours grows, so the previous whorl is taken per
//! section: each section of the inside whorl, reaching a few generating surfaces into its
//! neighbours so that the pieces join without a crease, less the sections one whorl before
//! it; the pieces meet as a union. B_{w−1} is the whorl of the body's point primitives (eq 9),
//! without the canal's cones: those lie along the axis, where every later canal runs, and
//! would fill the inner canal.

use super::fine_parts::SHOWS_THE_MODEL;
use super::generating_surface::generating_surface;
use super::helix::Instances;
use super::sections::Gathered;
use super::varix::{edge_distance, outward};
use crate::blobtree::blob_tree::Node;
use crate::blobtree::falloff::ISO;
use crate::blobtree::polygonize::MAX_LEVEL;
use crate::blobtree::texture_blend::Look;
use crate::mesh::Bounds;
use crate::spec::form::implicit::{GeneratorSpec, ImplicitSpec, Shows};
use glam::DVec3;

/// The thinnest wall the hollow leaves, as a fraction of the shell's extent (with its longest
/// spine); closer to the apex, where it would be thinner, the shell is solid. The model's own
/// size, the same at every resolution from 112 voxels up: 0.7/224, a quarter of a millimetre
/// on the 80 mm print the exporters default to, and [`WALL_VOXELS`] of a grid of 112 voxels
/// halved once, which the polygonizer halves where a wall is that thin (see
/// [`Opening::thin_walls`]).
pub const THINNEST_WALL: f64 = WALL_VOXELS / (SHOWS_THE_MODEL << MAX_LEVEL) as f64;

/// Voxels a wall is at least thick on a grid too coarse for [`THINNEST_WALL`] (under 112
/// voxels): thinner, the grid would show it perforated, in specks.
pub const WALL_VOXELS: f64 = 0.7;

/// Generating surfaces a piece of the hollow reaches into each neighbouring section, so that
/// where two pieces meet both are whole tubes and their union has no crease.
const OVERLAP: u32 = 2;

/// What eqs 14 and 15 carve out of the shell and add back.
pub(crate) struct Opening {
    /// B_inside of eq 14, the whorl of the inside generating surface (fig 10, centre).
    pub(crate) inside: Node,
    /// B_opening of eq 14.
    pub(crate) hollow: Node,
    /// B_inside_wall of eq 15, at the growing edge.
    pub(crate) wall: Option<Node>,
    /// The boxes of the generating surfaces whose wall is thinner than the grid's whole voxels
    /// show: hints for the polygonizer, which halves its voxels there.
    pub(crate) thin_walls: Vec<Bounds>,
}

/// The opening of eqs 14–15: the inside generating surface placed like the shell's, up to
/// `ahead` instances beyond the growing edge, each born `ahead` growth steps early, so that
/// the aperture is open at every stage. It starts where consecutive inside surfaces join into
/// one tube. `varices` are the spines and ridges of the varices (unplaced, with the instance
/// each closes), which the hollow leaves intact until the next whorl has grown over them.
/// `walls` are the thinnest wall it leaves ([`THINNEST_WALL`] of the shell's extent, or
/// [`WALL_VOXELS`] of a coarser grid) and the thinnest the grid's whole voxels show.
pub(crate) fn opening(
    spec: &ImplicitSpec,
    instances: &Instances,
    varices: &[(u32, Node)],
    walls: (f64, f64),
    shell: &Node,
    look: Look,
    gathered: &mut Gathered,
) -> Option<Opening> {
    let o = &spec.opening;
    let hollow = generating_surface(&o.inside, 0.0, f64::INFINITY)?;
    // The wall's thickness in units of D: the least of the spaces between the body's surface
    // and the inside one, swept along a stretch of the spiral, in eight directions of the
    // generating curve (those the body does not leave for a neighbouring whorl or the canal).
    let k0 = instances.count / 2;
    let swept = |g: &GeneratorSpec| {
        let placed = (k0.saturating_sub(3)..k0 + 4).filter_map(|k| {
            generating_surface(g, 0.0, f64::INFINITY)
                .map(|s| Node::transform(instances.placement(f64::from(k)), s))
        });
        Node::blend(placed.collect())
    };
    let (outer, inner) = (swept(&spec.generator), swept(&o.inside));
    let middle = instances.placement(f64::from(k0));
    let wall = (0..8)
        .filter_map(|i| {
            let d = outward(45.0 * f64::from(i));
            let outside = edge_distance(&outer, &middle, d)?;
            (outside < 2.0).then_some(outside - edge_distance(&inner, &middle, d)?)
        })
        .fold(f64::INFINITY, f64::min)
        .max(0.0);
    // The hollow starts where consecutive instances join into one tube: where the fields of
    // two neighbours sum past the iso-value halfway between their centres.
    let at = |k: u32| instances.placement(f64::from(k));
    let joins = |k: u32| {
        let (a, b) = (at(k), at(k + 1));
        let middle = (a.translation + b.translation) * 0.5;
        Node::transform(a, hollow.clone()).field(middle)
            + Node::transform(b, hollow.clone()).field(middle)
            >= ISO
    };
    let count = instances.count;
    let end = count + o.ahead;
    // It starts one generating surface after the first that joins the next, so that the apex
    // is closed by a cap as thick as the body's generating surface is about its centre.
    // Nor is it carved where the wall it leaves would be thinner than `thinnest_wall`; drawn
    // alone (fig 10), the inside whorl has no wall to keep, and starts where it joins.
    let apart = spec.opening.shows == Shows::Inside;
    let (thinnest_wall, shown_whole) = walls;
    let shown = |k: u32| apart || wall * instances.size(f64::from(k)) >= thinnest_wall;
    let first = (0..end).find(|&k| joins(k) && shown(k))? + 1;
    // The generating surface at instance k, for its pattern time and its parts present then.
    let surface = |g: &GeneratorSpec, k: u32| {
        let kf = f64::from(k);
        // The hollow ahead of the edge shows the edge's pattern on its inside.
        let time = instances.time(kf.min(f64::from(count - 1)));
        generating_surface(g, time, instances.whorl(kf))
    };
    let extension = GeneratorSpec {
        cones: o.extension.clone(),
        ..GeneratorSpec::default()
    };
    let points = GeneratorSpec {
        points: spec.generator.points.clone(),
        ..GeneratorSpec::default()
    };
    // The inside whorl's generating surfaces, each with its extension, for the pieces that
    // reach the previous whorl. Every piece has the previous whorl subtracted: an inside
    // whorl blended whole and left uncarved would reach through the previous whorl's wall
    // (the inside surface is nearly as large as the body's), leaving no wall between them.
    let mut extended: Vec<Option<Node>> = vec![None; first as usize];
    // Walls are hinted only where the shell is drawn: the solids drawn apart have none.
    let walled = spec.opening.shows == Shows::Shell;
    let mut thin_walls = Vec::new();
    for k in first..end {
        let birth = k.saturating_sub(o.ahead);
        let inside = surface(&o.inside, k);
        let parts: Vec<Node> = [inside, surface(&extension, k)]
            .into_iter()
            .flatten()
            .collect();
        let placed = (!parts.is_empty()).then(|| gathered.placed(at(k), Node::blend(parts), birth));
        let thickness = wall * instances.size(f64::from(k));
        if let Some(p) = placed
            .as_ref()
            .filter(|_| walled && thickness < shown_whole)
        {
            // The wall lies about the inside surface, within its thickness and a whole voxel.
            thin_walls.push(p.bounds.padded(thickness + shown_whole));
        }
        extended.push(placed);
    }
    // The body's whorl of points (eq 9), for the previous whorl.
    let points_whorl: Vec<Option<Node>> = (0..count)
        .map(|k| {
            let placed = instances.placement(f64::from(k));
            surface(&points, k).map(|s| Node::transform(placed, s).born_at(k))
        })
        .collect();
    let within = |nodes: &[Option<Node>], from: i64, to: i64| -> Vec<Node> {
        let (from, to) = (
            from.max(0) as usize,
            (to + 1).clamp(0, nodes.len() as i64) as usize,
        );
        nodes
            .get(from..to.max(from))
            .unwrap_or_default()
            .iter()
            .flatten()
            .cloned()
            .collect()
    };
    let (surfaces, per_whorl) = (
        i64::from(spec.surfaces),
        i64::from(spec.sections * spec.surfaces),
    );
    let overlap = i64::from(OVERLAP);
    let sections = (i64::from(end) + surfaces - 1) / surfaces;
    let mut pieces = Vec::new();
    let mut inside = Vec::new();
    for s in 0..sections {
        let (from, to) = (s * surfaces - overlap, (s + 1) * surfaces - 1 + overlap);
        let hollow = within(&extended, from, to);
        if hollow.is_empty() {
            continue;
        }
        let hollow = Node::blend(hollow);
        inside.push(hollow.clone());
        let previous = within(&points_whorl, from - per_whorl - 1, to - per_whorl + 1);
        pieces.push(if previous.is_empty() {
            hollow
        } else {
            Node::difference(hollow, Node::blend(previous))
        });
    }
    // A varix's spines stand out of the body; the next whorl grows over them, and its hollow
    // carves them where they cross it. Until that whorl's body is there, its hollow reaching
    // ahead of the growing edge leaves them intact, or it would cut them off their whorl.
    let over = per_whorl as u32 + o.ahead + 2;
    let intact: Vec<Node> = varices
        .iter()
        .map(|(k, spines)| {
            let at = instances.placement(f64::from(*k));
            gathered.placed_living(at, spines.clone(), *k, k + over)
        })
        .collect();
    let hollow = Node::union(pieces);
    let hollow = if intact.is_empty() {
        hollow
    } else {
        Node::difference(hollow, Node::union(intact))
    };
    Some(Opening {
        inside: Node::union(inside),
        hollow,
        wall: inside_wall(spec, instances, first, shell, look, gathered),
        thin_walls,
    })
}

/// B_inside_wall of eq 15: over the last `spec.opening.wall` generating surfaces at the
/// growing edge, the shell itself within a ball about each one's centre, less the inside
/// generating surface without its extension (and less the previous whorl's hollow, which
/// the ball reaches into): the body's own inner wall where the extension carved it away.
/// The ball reaches past the extension's far end by the extension's own width, so that its
/// trailing end crosses the previous whorl's surface and never meets it tangentially (a
/// ball just touching it would enclose slivers of hollow between the two). Taking the shell
/// within it, rather than the body's points, keeps the wall's outer surface the shell's own.
/// Each generating surface's part lives from the growth step that places it to the step that
/// moves the edge past the wall.
fn inside_wall(
    spec: &ImplicitSpec,
    instances: &Instances,
    first: u32,
    shell: &Node,
    look: Look,
    gathered: &mut Gathered,
) -> Option<Node> {
    let o = &spec.opening;
    let n = o.wall;
    if n == 0 {
        return None;
    }
    let reach = o
        .extension
        .iter()
        .map(|c| DVec3::new(c[3], c[4], c[5]).length() + c[6].max(c[7]))
        .chain(spec.generator.points.iter().map(|p| p[3]))
        .fold(0.0, f64::max);
    let ball = GeneratorSpec {
        points: vec![[0.0, 0.0, 0.0, reach]],
        ..GeneratorSpec::default()
    };
    let extended = GeneratorSpec {
        cones: [o.inside.cones.as_slice(), o.extension.as_slice()].concat(),
        ..o.inside.clone()
    };
    let count = instances.count;
    let per_whorl = spec.sections * spec.surfaces;
    let time = |k: u32| instances.time(f64::from(k.min(count - 1)));
    let surface =
        |g: &GeneratorSpec, k: u32| generating_surface(g, time(k), instances.whorl(f64::from(k)));
    let at = |k: u32| instances.placement(f64::from(k));
    let mut balls = Vec::new();
    let mut round = Vec::new();
    let mut previous = Vec::new();
    for k in first..count + o.ahead {
        if k < count
            && let Some(b) = surface(&ball, k)
        {
            balls.push(gathered.placed_living(at(k), b, k, k + n));
        }
        // The hollow of this wall reaches one generating surface behind it, and ahead.
        if let Some(g) = surface(&o.inside, k) {
            round.push(gathered.placed_living(at(k), g, k.saturating_sub(o.ahead), k + n + 1));
        }
        // The previous whorl's hollow, extension included, under the wall.
        if k + per_whorl < count
            && let Some(g) = surface(&extended, k)
        {
            let (birth, death) = (k + per_whorl - OVERLAP, k + per_whorl + n + OVERLAP);
            previous.push(gathered.placed_living(at(k), g, birth, death));
        }
    }
    if balls.is_empty() {
        return None;
    }
    let mut carved = vec![Node::blend(round)];
    if !previous.is_empty() {
        carved.push(Node::blend(previous));
    }
    // The wall looks like the body it is part of; the shell within it keeps its own looks.
    let looking = |node: Node| match look {
        Look::Pattern => node,
        _ => node.looking(look),
    };
    Some(Node::difference(
        Node::intersection(vec![looking(Node::blend(balls)), shell.clone()]),
        looking(Node::union(carved)),
    ))
}
