//! The BlobTree (Wyvill, Guy & Galin 1999; Galbraith, Prusinkiewicz & Wyvill §2.2): skeletal
//! primitives at the leaves, and as interior nodes the operators union ∪, intersection ∩ and
//! difference − (CSG), blend + (the sum of fields), superelliptic blend (eqs 4–5), controlled
//! blend (eq 6), the bend warp, and affine transforms. Every node knows the box outside which
//! its field is zero, so evaluation skips every subtree a point misses, and [`Node::cull`] cuts
//! a tree down to the few primitives near a region before it is sampled there. Every node also
//! carries the growth steps it lives through (born at one, gone at another, or never), so one
//! tree describes the shape at every stage of its growth.

use super::bend::Bend;
use super::falloff::ISO;
use super::primitive::Primitive;
use super::texture_blend::{Look, Paint, Texture};
use crate::mesh::Bounds;
use glam::{DAffine3, DMat3, DVec3};
use std::rc::Rc;

/// An affine map with its inverse (fields are evaluated through the inverse).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Affine {
    pub forward: DAffine3,
    inverse: DAffine3,
    /// A bound on how much the inverse stretches distances (its spectral norm).
    stretch: f64,
}

impl Affine {
    pub fn new(forward: DAffine3) -> Self {
        let inverse = forward.inverse();
        Self {
            forward,
            inverse,
            stretch: spectral_norm(inverse.matrix3),
        }
    }
}

/// ‖M‖₂ as the square root of the largest eigenvalue of MᵀM, by power iteration, rounded up by
/// a hair: a bound on the stretch must not be too small.
fn spectral_norm(m: DMat3) -> f64 {
    let mtm = m.transpose() * m;
    let mut v = DVec3::new(0.577, 0.578, 0.579);
    let mut lambda = 0.0;
    for _ in 0..64 {
        let w = mtm * v;
        lambda = w.length();
        if lambda == 0.0 {
            return 0.0;
        }
        v = w / lambda;
    }
    lambda.sqrt() * 1.001
}

/// Bounds (lowest, highest) on a field over a region.
pub type Range = (f64, f64);

/// What a node does.
#[derive(Clone, Debug, PartialEq)]
pub enum Op {
    Leaf(Primitive, Rc<Texture>),
    /// + : the sum of the fields: everything blends with everything.
    Blend(Vec<Node>),
    /// ∪ : the largest field.
    Union(Vec<Node>),
    /// ∩ : the smallest field.
    Intersection(Vec<Node>),
    /// A − B : min(f_A, 2·iso − f_B), never below zero (eq 14's carving).
    Difference(Box<Node>, Box<Node>),
    /// Eq 4: (Σ fᵢⁿ)^(1/n), from the blend (n = 1) towards the union (eq 5, n → ∞).
    Superelliptic(f64, Vec<Node>),
    /// Eq 6: only the listed pairs blend; f = max over the pairs of fᵢ + f_k and over the
    /// children alone of fᵢ, so two children that are not paired meet as in a union.
    Controlled(Vec<Node>, Vec<[usize; 2]>),
    /// w : the child seen through a bend.
    Warp(Bend, Box<Node>),
    /// t, s, r : the child moved by an affine map.
    Transform(Rc<Affine>, Box<Node>),
}

/// A BlobTree node with what evaluation and culling need to know of it.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    pub op: Op,
    /// Outside this box the field is zero.
    pub bounds: Bounds,
    /// The growth step at which the node appears.
    pub birth: u32,
    /// The growth step from which it is gone (`u32::MAX`: never).
    pub death: u32,
}

fn fold(children: &[Node], f: impl Fn(&Node) -> f64, g: fn(f64, f64) -> f64, zero: f64) -> f64 {
    children.iter().map(f).fold(zero, g)
}

impl Node {
    fn new(op: Op) -> Self {
        let (bounds, (birth, death)) = match &op {
            Op::Leaf(p, _) => (p.bounds(), (0, u32::MAX)),
            Op::Blend(c) | Op::Superelliptic(_, c) | Op::Union(c) | Op::Controlled(c, _) => {
                (union_bounds(c), lifetime(c))
            }
            Op::Intersection(c) => (
                c.iter()
                    .map(|n| n.bounds)
                    .reduce(|a, b| a.intersection(&b))
                    .unwrap_or(Bounds::EMPTY),
                (
                    c.iter().map(|n| n.birth).max().unwrap_or(0),
                    c.iter().map(|n| n.death).min().unwrap_or(u32::MAX),
                ),
            ),
            Op::Difference(a, _) => (a.bounds, (a.birth, a.death)),
            Op::Warp(bend, child) => (bend.bounds(&child.bounds), (child.birth, child.death)),
            Op::Transform(affine, child) => {
                let mut b = Bounds::EMPTY;
                for corner in child.bounds.corners() {
                    b.include(affine.forward.transform_point3(corner));
                }
                (b, (child.birth, child.death))
            }
        };
        Self {
            op,
            bounds,
            birth,
            death,
        }
    }

    pub fn leaf(primitive: Primitive, texture: Texture) -> Self {
        Self::new(Op::Leaf(primitive, Rc::new(texture)))
    }

    /// The same tree with every primitive showing `look` (a part textured as a whole, §3.4).
    pub fn looking(self, look: Look) -> Self {
        let all = |c: Vec<Node>| c.into_iter().map(|n| n.looking(look)).collect();
        let op = match self.op {
            Op::Leaf(p, t) => Op::Leaf(p, Rc::new(t.looking(look))),
            Op::Blend(c) => Op::Blend(all(c)),
            Op::Union(c) => Op::Union(all(c)),
            Op::Intersection(c) => Op::Intersection(all(c)),
            Op::Superelliptic(n, c) => Op::Superelliptic(n, all(c)),
            Op::Controlled(c, pairs) => Op::Controlled(all(c), pairs),
            Op::Difference(a, b) => {
                Op::Difference(Box::new(a.looking(look)), Box::new(b.looking(look)))
            }
            Op::Warp(bend, c) => Op::Warp(bend, Box::new(c.looking(look))),
            Op::Transform(affine, c) => Op::Transform(affine, Box::new(c.looking(look))),
        };
        Self { op, ..self }
    }

    /// Blends nested in the children are spliced in: the sum is associative.
    pub fn blend(children: Vec<Node>) -> Self {
        let mut flat = Vec::with_capacity(children.len());
        for child in children {
            match child.op {
                Op::Blend(inner) => flat.extend(inner),
                _ => flat.push(child),
            }
        }
        Self::new(Op::Blend(flat))
    }

    pub fn union(children: Vec<Node>) -> Self {
        Self::new(Op::Union(children))
    }

    pub fn intersection(children: Vec<Node>) -> Self {
        Self::new(Op::Intersection(children))
    }

    pub fn difference(a: Node, b: Node) -> Self {
        Self::new(Op::Difference(Box::new(a), Box::new(b)))
    }

    /// Eq 4 with exponent `n` ≥ 1.
    pub fn superelliptic(n: f64, children: Vec<Node>) -> Self {
        Self::new(Op::Superelliptic(n, children))
    }

    /// Eq 6: `pairs` index into `children`.
    pub fn controlled(children: Vec<Node>, pairs: Vec<[usize; 2]>) -> Self {
        Self::new(Op::Controlled(children, pairs))
    }

    /// The child seen through `bend`; a bend of no angle is the child itself, so that a
    /// straight cone's placing can be pushed down to it and nothing evaluates the identity.
    pub fn warp(bend: Bend, child: Node) -> Self {
        if bend.is_straight() {
            return child;
        }
        Self::new(Op::Warp(bend, Box::new(child)))
    }

    /// The child moved by `forward`. A similarity is pushed down to the primitives (a moved
    /// point is a point), and transforms meet in one, so that evaluation does not pass through
    /// a chain of maps.
    pub fn transform(forward: DAffine3, child: Node) -> Self {
        let (birth, death) = (child.birth, child.death);
        let moved = match child.op {
            Op::Transform(inner, grandchild) => Self::new(Op::Transform(
                Rc::new(Affine::new(forward * inner.forward)),
                grandchild,
            )),
            op => match similarity_scale(forward) {
                Some(scale) => Self::new(push(op, forward, scale)),
                None => Self::new(Op::Transform(
                    Rc::new(Affine::new(forward)),
                    Box::new(Self::new(op)),
                )),
            },
        };
        Node {
            birth,
            death,
            ..moved
        }
    }

    /// The same subtree, appearing at growth step `step` (every node in it), for good.
    pub fn born_at(self, step: u32) -> Self {
        self.living(step, u32::MAX)
    }

    /// The same subtree, appearing at growth step `birth` and gone from step `death` on (every
    /// node in it): a part of a shell that only its growing edge has.
    pub fn living(mut self, birth: u32, death: u32) -> Self {
        self.birth = birth;
        self.death = death;
        match &mut self.op {
            Op::Leaf(..) => {}
            Op::Blend(c)
            | Op::Union(c)
            | Op::Intersection(c)
            | Op::Superelliptic(_, c)
            | Op::Controlled(c, _) => {
                for child in c.iter_mut() {
                    *child = std::mem::replace(child, placeholder()).living(birth, death);
                }
            }
            Op::Difference(a, b) => {
                **a = std::mem::replace(&mut **a, placeholder()).living(birth, death);
                **b = std::mem::replace(&mut **b, placeholder()).living(birth, death);
            }
            Op::Warp(_, c) | Op::Transform(_, c) => {
                **c = std::mem::replace(&mut **c, placeholder()).living(birth, death);
            }
        }
        self
    }

    /// Whether the node is there at growth step `step` (a node that never goes is there at
    /// every step from its birth, `u32::MAX` included).
    pub fn alive(&self, step: u32) -> bool {
        self.birth <= step && (step < self.death || self.death == u32::MAX)
    }

    /// The field at `p`. The test of the box and the leaves are inlined into the operators
    /// (most children a point meets are out of range or primitives); operators are calls.
    #[inline]
    pub fn field(&self, p: DVec3) -> f64 {
        if !self.bounds.contains(p) {
            return 0.0;
        }
        match &self.op {
            Op::Leaf(primitive, _) => primitive.field(p),
            _ => self.operator_field(p),
        }
    }

    /// [`Node::field`] of an operator.
    #[inline(never)]
    fn operator_field(&self, p: DVec3) -> f64 {
        match &self.op {
            Op::Leaf(primitive, _) => primitive.field(p),
            Op::Blend(c) => c.iter().map(|n| n.field(p)).sum(),
            Op::Union(c) => fold(c, |n| n.field(p), f64::max, 0.0),
            Op::Intersection(c) => fold(c, |n| n.field(p), f64::min, f64::INFINITY),
            Op::Difference(a, b) => difference(a.field(p), b.field(p)),
            Op::Superelliptic(n, c) => with_children(
                c,
                |child| child.field(p),
                |fields| superelliptic(*n, fields),
            ),
            Op::Controlled(c, pairs) => with_children(
                c,
                |child| child.field(p),
                |fields| controlled(fields.len(), |i| fields[i], pairs).0,
            ),
            Op::Warp(bend, child) => child.field(bend.inverse(p)),
            Op::Transform(affine, child) => child.field(affine.inverse.transform_point3(p)),
        }
    }

    /// The field at `p` (as [`Node::field`] gives it), its gradient, exact operator by operator
    /// (the chain rule through primitives, transforms and bends; the winning child of a union,
    /// intersection or difference; eq 4's weights (fᵢ/f)ⁿ⁻¹), and the blended pattern
    /// coordinates of the primitives that make it: all a surface vertex needs, in one walk.
    #[inline]
    pub fn probe(&self, p: DVec3) -> Probe {
        if !self.bounds.contains(p) {
            return Probe::default();
        }
        match &self.op {
            Op::Leaf(primitive, texture) => leaf_probe(primitive, texture, p),
            _ => self.operator_probe(p),
        }
    }

    /// [`Node::probe`] of an operator.
    #[inline(never)]
    fn operator_probe(&self, p: DVec3) -> Probe {
        match &self.op {
            Op::Leaf(primitive, texture) => leaf_probe(primitive, texture, p),
            Op::Blend(c) => c
                .iter()
                .map(|n| n.probe(p))
                .fold(Probe::default(), |sum, x| Probe {
                    field: sum.field + x.field,
                    gradient: sum.gradient + x.gradient,
                    paint: sum.paint + x.paint,
                }),
            Op::Superelliptic(n, c) => with_children(
                c,
                |child| child.probe(p),
                |parts| {
                    let fields = |i: usize| parts[i].field;
                    let f = superelliptic_of(*n, parts.len(), fields);
                    let mut out = Probe {
                        field: f,
                        ..Probe::default()
                    };
                    for part in parts {
                        out.paint = out.paint + part.paint;
                        if part.field > 0.0 {
                            out.gradient += part.gradient * libm::pow(part.field / f, n - 1.0);
                        }
                    }
                    out
                },
            ),
            Op::Union(c) => strongest(c.iter().map(|n| n.probe(p)), |a, b| a > b),
            Op::Intersection(c) => strongest(c.iter().map(|n| n.probe(p)), |a, b| a < b),
            Op::Difference(a, b) => {
                let (a, b) = (a.probe(p), b.probe(p));
                let f = difference(a.field, b.field);
                if b.field == 0.0 || f == a.field {
                    Probe { field: f, ..a }
                } else {
                    Probe {
                        field: f,
                        gradient: if f > 0.0 { -b.gradient } else { DVec3::ZERO },
                        paint: b.paint.carved(),
                    }
                }
            }
            Op::Controlled(c, pairs) => with_children(
                c,
                |child| child.probe(p),
                |parts| {
                    let (f, [i, k]) = controlled(parts.len(), |i| parts[i].field, pairs);
                    if i == k {
                        Probe {
                            field: f,
                            ..parts[i]
                        }
                    } else {
                        Probe {
                            field: f,
                            gradient: parts[i].gradient + parts[k].gradient,
                            paint: parts[i].paint + parts[k].paint,
                        }
                    }
                },
            ),
            // Where the child has no field, neither has it a gradient to carry back.
            Op::Warp(bend, child) => {
                let place = bend.place(p);
                let inner = child.probe(bend.unbend(p, place));
                if inner.field == 0.0 {
                    return inner;
                }
                Probe {
                    gradient: bend.jacobian(place).transpose() * inner.gradient,
                    ..inner
                }
            }
            Op::Transform(affine, child) => {
                let inner = child.probe(affine.inverse.transform_point3(p));
                if inner.field == 0.0 {
                    return inner;
                }
                Probe {
                    gradient: affine.inverse.matrix3.transpose() * inner.gradient,
                    ..inner
                }
            }
        }
    }

    /// Bounds (lowest, highest) on the field throughout the ball of `reach` about `centre`,
    /// carried up the tree by interval arithmetic: every operator but the difference is
    /// increasing in each child's field, so it maps the children's bounds to its own; the ball
    /// passes through transforms and bends stretched by at most their stretch there.
    pub fn range(&self, centre: DVec3, reach: f64) -> Range {
        let ball = Bounds {
            min: centre - reach,
            max: centre + reach,
        };
        if !self.bounds.intersects(&ball) {
            return (0.0, 0.0);
        }
        let each = |c: &[Node], f: &dyn Fn(&[Range]) -> Range| {
            with_children(c, |n| n.range(centre, reach), f)
        };
        match &self.op {
            Op::Leaf(primitive, _) => primitive.range(centre, reach),
            Op::Blend(c) => each(c, &|r| {
                r.iter().fold((0.0, 0.0), |s, x| (s.0 + x.0, s.1 + x.1))
            }),
            Op::Union(c) => each(c, &|r| {
                r.iter()
                    .fold((0.0, 0.0), |s, x| (s.0.max(x.0), s.1.max(x.1)))
            }),
            Op::Intersection(c) => each(c, &|r| {
                r.iter().fold((f64::INFINITY, f64::INFINITY), |s, x| {
                    (s.0.min(x.0), s.1.min(x.1))
                })
            }),
            Op::Difference(a, b) => {
                let ((la, ha), (lb, hb)) = (a.range(centre, reach), b.range(centre, reach));
                let hi = if lb == 0.0 {
                    ha
                } else {
                    ha.min(2.0 * ISO - lb).max(0.0)
                };
                (la.min(2.0 * ISO - hb).max(0.0), hi)
            }
            Op::Superelliptic(n, c) => each(c, &|r| {
                (
                    superelliptic_of(*n, r.len(), |i| r[i].0),
                    superelliptic_of(*n, r.len(), |i| r[i].1),
                )
            }),
            Op::Controlled(c, pairs) => each(c, &|r| {
                (
                    controlled(r.len(), |i| r[i].0, pairs).0,
                    controlled(r.len(), |i| r[i].1, pairs).0,
                )
            }),
            Op::Warp(bend, child) => match bend.inverse_ball(centre, reach) {
                Some((centre, reach)) => child.range(centre, reach),
                None => (0.0, f64::INFINITY),
            },
            Op::Transform(affine, child) => child.range(
                affine.inverse.transform_point3(centre),
                reach * affine.stretch,
            ),
        }
    }

    /// The part of the tree that matters inside `region` at growth step `step`: subtrees born
    /// later, gone already, or whose boxes miss the region are dropped, and so are operators
    /// left with one child. `None` when the field is zero throughout the region.
    pub fn cull(&self, region: &Bounds, step: u32) -> Option<Node> {
        if !self.alive(step) || !self.bounds.intersects(region) {
            return None;
        }
        let many = |c: &[Node], make: &dyn Fn(Vec<Node>) -> Node| {
            let mut kept: Vec<Node> = c.iter().filter_map(|n| n.cull(region, step)).collect();
            match kept.len() {
                0 => None,
                1 => kept.pop(),
                _ => Some(make(kept)),
            }
        };
        match &self.op {
            Op::Leaf(primitive, _) => {
                // Tighter than the boxes for long slanted cones and the hole of a torus.
                let reach = (region.max - region.min).length() * 0.5;
                (primitive.range(region.center(), reach).1 > 0.0).then(|| self.clone())
            }
            Op::Blend(c) => many(c, &Node::blend),
            Op::Union(c) => many(c, &Node::union),
            Op::Superelliptic(n, c) => many(c, &|kept| Node::superelliptic(*n, kept)),
            Op::Intersection(c) => c
                .iter()
                .map(|n| n.cull(region, step))
                .collect::<Option<Vec<Node>>>()
                .map(Node::intersection),
            Op::Difference(a, b) => {
                let a = a.cull(region, step)?;
                Some(match b.cull(region, step) {
                    Some(b) => Node::difference(a, b),
                    None => a,
                })
            }
            Op::Controlled(c, pairs) => {
                let mut index = vec![usize::MAX; c.len()];
                let mut kept = Vec::new();
                for (i, child) in c.iter().enumerate() {
                    if let Some(child) = child.cull(region, step) {
                        index[i] = kept.len();
                        kept.push(child);
                    }
                }
                let pairs: Vec<[usize; 2]> = pairs
                    .iter()
                    .map(|[i, k]| [index[*i], index[*k]])
                    .filter(|[i, k]| *i != usize::MAX && *k != usize::MAX)
                    .collect();
                match kept.len() {
                    0 => None,
                    1 => kept.pop(),
                    _ if pairs.is_empty() => Some(Node::union(kept)),
                    _ => Some(Node::controlled(kept, pairs)),
                }
            }
            Op::Warp(bend, child) => {
                // The ball around the region maps through the inverse bend into a ball;
                // where that is unbounded, the whole child is kept.
                let region = region.intersection(&self.bounds);
                let reach = (region.max - region.min).length() * 0.5;
                let local = match bend.inverse_ball(region.center(), reach) {
                    Some((centre, reach)) => Bounds {
                        min: centre - reach,
                        max: centre + reach,
                    },
                    None => child.bounds,
                };
                let child = child.cull(&local, step)?;
                // The bent box of the whole child still holds the culled child's field, and
                // bending a box anew would cost more than the cull saves.
                Some(Node {
                    op: Op::Warp(*bend, Box::new(child)),
                    ..*self
                })
            }
            Op::Transform(affine, child) => {
                let mut local = Bounds::EMPTY;
                for corner in region.intersection(&self.bounds).corners() {
                    local.include(affine.inverse.transform_point3(corner));
                }
                let child = child.cull(&local, step)?;
                Some(Node {
                    op: Op::Transform(affine.clone(), Box::new(child)),
                    ..*self
                })
            }
        }
    }
}

/// [`Node::probe`] of a primitive.
fn leaf_probe(primitive: &Primitive, texture: &Texture, p: DVec3) -> Probe {
    let (f, gradient) = primitive.field_gradient(p);
    // A primitive adds no weight to the pattern coordinates where its field is zero.
    let paint = if f > 0.0 {
        Paint::of(texture, primitive, p, f)
    } else {
        Paint::default()
    };
    Probe {
        field: f,
        gradient,
        paint,
    }
}

/// Calls `f` with what `each` gives for every child, kept on the stack for the few children a
/// culled tree has.
fn with_children<T: Copy + Default, R>(
    children: &[Node],
    each: impl Fn(&Node) -> T,
    f: impl FnOnce(&[T]) -> R,
) -> R {
    const FEW: usize = 16;
    if children.len() <= FEW {
        let mut values = [T::default(); FEW];
        for (slot, child) in values.iter_mut().zip(children) {
            *slot = each(child);
        }
        f(&values[..children.len()])
    } else {
        f(&children.iter().map(each).collect::<Vec<T>>())
    }
}

/// The factor by which `m` scales every length, when it is a similarity.
fn similarity_scale(m: DAffine3) -> Option<f64> {
    let [a, b, c] = [m.matrix3.x_axis, m.matrix3.y_axis, m.matrix3.z_axis];
    let s = a.length();
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * s * s;
    let similar = close(b.length_squared(), s * s)
        && close(c.length_squared(), s * s)
        && close(a.dot(b), 0.0)
        && close(b.dot(c), 0.0)
        && close(a.dot(c), 0.0);
    (similar && s > 0.0).then_some(s)
}

/// An operator whose every primitive is moved by the similarity `m` of scale `scale`.
fn push(op: Op, m: DAffine3, scale: f64) -> Op {
    let all = |c: Vec<Node>| c.into_iter().map(|n| Node::transform(m, n)).collect();
    match op {
        Op::Leaf(p, t) => Op::Leaf(p.moved(&m, scale), Rc::new(t.moved(m.inverse()))),
        Op::Blend(c) => Op::Blend(all(c)),
        Op::Union(c) => Op::Union(all(c)),
        Op::Intersection(c) => Op::Intersection(all(c)),
        Op::Superelliptic(n, c) => Op::Superelliptic(n, all(c)),
        Op::Controlled(c, pairs) => Op::Controlled(all(c), pairs),
        Op::Difference(a, b) => Op::Difference(
            Box::new(Node::transform(m, *a)),
            Box::new(Node::transform(m, *b)),
        ),
        Op::Warp(bend, c) => Op::Transform(
            Rc::new(Affine::new(m)),
            Box::new(Node::new(Op::Warp(bend, c))),
        ),
        Op::Transform(..) => unreachable!("transforms are composed, not pushed"),
    }
}

/// A stand-in moved out of a node for a moment while its children are rebuilt.
fn placeholder() -> Node {
    Node {
        op: Op::Blend(Vec::new()),
        bounds: Bounds::EMPTY,
        birth: 0,
        death: u32::MAX,
    }
}

fn union_bounds(children: &[Node]) -> Bounds {
    children
        .iter()
        .fold(Bounds::EMPTY, |b, n| b.union(&n.bounds))
}

/// The steps some child lives through: from the first birth to the last death.
fn lifetime(children: &[Node]) -> (u32, u32) {
    (
        children.iter().map(|n| n.birth).min().unwrap_or(0),
        children.iter().map(|n| n.death).max().unwrap_or(u32::MAX),
    )
}

/// The child whose field wins the comparison `better`.
fn strongest(parts: impl Iterator<Item = Probe>, better: fn(f64, f64) -> bool) -> Probe {
    parts
        .reduce(|a, b| if better(b.field, a.field) { b } else { a })
        .unwrap_or_default()
}

/// A − B: min(f_A, 2·iso − f_B), never below zero; exactly f_A where B has no field, so
/// that a tree culled to a region without B gives the same samples as the whole tree.
fn difference(fa: f64, fb: f64) -> f64 {
    if fb == 0.0 {
        fa
    } else {
        fa.min(2.0 * ISO - fb).max(0.0)
    }
}

/// Eq 4, computed as m·(Σ (fᵢ/m)ⁿ)^(1/n) with m the largest field, so that n = 400 neither
/// overflows nor underflows.
pub fn superelliptic(n: f64, fields: &[f64]) -> f64 {
    superelliptic_of(n, fields.len(), |i| fields[i])
}

/// Eq 4 over the `count` fields that `field` gives by index.
fn superelliptic_of(n: f64, count: usize, field: impl Fn(usize) -> f64) -> f64 {
    let m = (0..count).map(&field).fold(0.0, f64::max);
    if m <= 0.0 {
        return 0.0;
    }
    let sum: f64 = (0..count).map(|i| libm::pow(field(i) / m, n)).sum();
    m * libm::pow(sum, 1.0 / n)
}

/// Eq 6: the largest of the paired sums and the single fields among the `count` that `field`
/// gives by index, with the pair that gives it ([i, i] for a single).
fn controlled(
    count: usize,
    field: impl Fn(usize) -> f64,
    pairs: &[[usize; 2]],
) -> (f64, [usize; 2]) {
    let mut best = (0.0, [0, 0]);
    for i in 0..count {
        let f = field(i);
        if f > best.0 {
            best = (f, [i, i]);
        }
    }
    for &[i, k] in pairs {
        let f = field(i) + field(k);
        if f > best.0 {
            best = (f, [i, k]);
        }
    }
    best
}

/// The field, its gradient and the blended textures at a point.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Probe {
    pub field: f64,
    pub gradient: DVec3,
    pub paint: Paint,
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    #[test]
    fn a_straight_bend_is_its_child_and_a_placed_straight_cone_one_primitive() {
        let cone = Node::leaf(
            Primitive::Cone {
                from: DVec3::ZERO,
                to: DVec3::X * 2.0,
                radii: [0.4, 0.2],
            },
            Texture::around(0.0),
        );
        assert_eq!(Node::warp(Bend::new(0.0, 2.0), cone.clone()), cone);
        let rigid = DAffine3::from_rotation_translation(
            DQuat::from_rotation_z(0.7),
            DVec3::new(1.0, -2.0, 0.5),
        );
        let placed = Node::transform(rigid, Node::warp(Bend::new(0.0, 2.0), cone.clone()));
        assert!(matches!(placed.op, Op::Leaf(..)), "{:?}", placed.op);
        let bent = Node::transform(rigid, Node::warp(Bend::new(0.3, 2.0), cone.clone()));
        assert!(matches!(bent.op, Op::Transform(..)), "{:?}", bent.op);
        for q in [
            DVec3::new(-0.5, 0.1, 0.2),
            DVec3::new(0.7, -0.2, 0.0),
            DVec3::new(1.9, 0.3, -0.1),
        ] {
            let (p, through) = (rigid.transform_point3(q), cone.field(q));
            assert!((placed.field(p) - through).abs() < 1e-12, "at {q}");
        }
    }
}
