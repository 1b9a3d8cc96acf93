//! Where the surface crosses an edge of the tetrahedra: the one vertex every piece that has
//! the edge computes alike, bit for bit.

use crate::blobtree::blob_tree::{Node, Probe};
use crate::blobtree::falloff::ISO;
use crate::mesh::{Surface, Vertex};
use glam::DVec3;

/// The vertex where the field crosses the iso-value on the grid edge between two samples
/// (position, field): one probe of the tree at the linear interpolation of the samples gives
/// the field there, its exact gradient (the normal) and the primitives' blended textures, and
/// one Newton step along the edge with that gradient moves the vertex onto the surface. It is
/// kept off the edge's ends, so that vertices of different edges never coincide.
pub(super) fn surface_vertex(tree: &Node, ends: [(DVec3, f64); 2]) -> Vertex {
    let [(pa, fa), (pb, fb)] = ends;
    let edge = pb - pa;
    let guess = ((ISO - fa) / (fb - fa)).clamp(1e-3, 1.0 - 1e-3);
    let Probe {
        field,
        gradient,
        paint,
    } = tree.probe(pa + edge * guess);
    let newton = guess - (field - ISO) / gradient.dot(edge);
    let t = if newton.is_finite() {
        newton.clamp(1e-3, 1.0 - 1e-3)
    } else {
        guess
    };
    let p = pa + edge * t;
    let normal = (-gradient)
        .try_normalize()
        .unwrap_or(edge.normalize() * -(fb - fa).signum());
    let surface = if paint.inner {
        Surface::Inner
    } else {
        Surface::Outer
    };
    Vertex::new(p, normal, paint.coordinates(), surface).tinted(paint.tint())
}
