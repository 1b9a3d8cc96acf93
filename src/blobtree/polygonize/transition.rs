//! Whole voxels beside halved ones, split to meet them (see `refinement.rs`): the rule that
//! makes the tetrahedra of both levels share their faces, and marching tetrahedra over
//! tetrahedra of any shape. Points are finest indices: the lattice of halved voxels, on which
//! a whole voxel's corners are the even points, its edges' midpoints, its faces' centres and
//! its centre the others.
//!
//! The rule, for a whole voxel:
//! - an edge of it is split at its midpoint where any voxel around the edge is halved;
//! - a face is split into the Kuhn triangles of its four halves where the voxel across it is
//!   halved (as that voxel's own tetrahedra split it), fanned from its centre through its
//!   corners and split edges' midpoints where one of its edges is split, and otherwise split
//!   by its Kuhn diagonal (as a whole voxel's six tetrahedra split it);
//! - the voxel is coned from its centre over its faces' triangles when one of its edges is
//!   split, and split into Kuhn's six tetrahedra otherwise.
//!
//! Each face's split depends only on the voxels beside it and around its edges, so the two
//! voxels sharing a face split it alike. Coning (rather than Lengyel's Transvoxel cells) needs
//! no table of cases and places every sample on the finest lattice, where it is the field
//! itself; it costs a few more tetrahedra in the voxels beside a halved one, which are few.

/// A point of the finest lattice.
pub(super) type Point = [i64; 3];

/// The tetrahedra of the whole voxel `v` (global index of level 0) split to meet its halved
/// neighbours (`halved` says which voxels are), as four points each, the last the voxel's
/// centre; `None` when none of its edges is split and it takes Kuhn's six tetrahedra.
pub(super) fn coned(v: [i64; 3], halved: &dyn Fn([i64; 3]) -> bool) -> Option<Vec<[Point; 4]>> {
    let base = v.map(|c| 2 * c);
    // Whether the edge along `axis` whose other coordinates are offset by `at` (0 or 1
    // voxel) from the voxel's lowest corner is split: a voxel around it is halved.
    let split = |axis: usize, at: [i64; 3]| {
        let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
        (0..4).any(|n| {
            let mut w = v;
            w[b] += at[b] - (n & 1);
            w[c] += at[c] - (n >> 1 & 1);
            halved(w)
        })
    };
    let any_split = (0..3).any(|axis| {
        (0..4).any(|n| {
            let mut at = [0; 3];
            at[(axis + 1) % 3] = n & 1;
            at[(axis + 2) % 3] = n >> 1 & 1;
            split(axis, at)
        })
    });
    if !any_split {
        return None;
    }
    let centre = base.map(|c| c + 1);
    let mut tets = Vec::new();
    for axis in 0..3 {
        let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
        for side in 0..2 {
            // The face's point (i, j) along its axes u and w, each 0, 1 or 2.
            let at = |i: i64, j: i64| {
                let mut p = base;
                p[axis] += 2 * side;
                p[u] += i;
                p[w] += j;
                p
            };
            let mut across = v;
            across[axis] += 2 * side - 1;
            let mut triangles: Vec<[Point; 3]> = Vec::new();
            if halved(across) {
                for (i, j) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                    triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            } else {
                // Its edges in order around it: along u at w = 0, along w at u = 2, along u
                // at w = 2, along w at u = 0; each with its start and midpoint.
                let edge = |along: usize, fixed: usize, offset: i64| {
                    let mut o = [0; 3];
                    o[axis] = side;
                    o[fixed] = offset;
                    split(along, o)
                };
                let ring = [
                    (at(0, 0), at(1, 0), edge(u, w, 0)),
                    (at(2, 0), at(2, 1), edge(w, u, 1)),
                    (at(2, 2), at(1, 2), edge(u, w, 1)),
                    (at(0, 2), at(0, 1), edge(w, u, 0)),
                ];
                if ring.iter().any(|r| r.2) {
                    let mut around = Vec::new();
                    for &(corner, middle, split) in &ring {
                        around.push(corner);
                        if split {
                            around.push(middle);
                        }
                    }
                    for n in 0..around.len() {
                        triangles.push([at(1, 1), around[n], around[(n + 1) % around.len()]]);
                    }
                } else {
                    triangles.push([at(0, 0), at(2, 0), at(2, 2)]);
                    triangles.push([at(0, 0), at(2, 2), at(0, 2)]);
                }
            }
            tets.extend(triangles.into_iter().map(|[a, b, c]| [a, b, c, centre]));
        }
    }
    Some(tets)
}

/// How the surface cuts the tetrahedron `corners` with the corners `inside` inside: at most
/// two triangles, each as three of its edges (pairs of corner numbers), wound to face from
/// the inside corners towards the outside ones, judged with each vertex at its edge's
/// midpoint (as `tetrahedra.rs` judges Kuhn's).
pub(super) fn cut(corners: &[Point; 4], inside: [bool; 4]) -> Vec<[(usize, usize); 3]> {
    let ins: Vec<usize> = (0..4).filter(|&i| inside[i]).collect();
    let outs: Vec<usize> = (0..4).filter(|&i| !inside[i]).collect();
    let crossing = |a: usize, b: usize| -> (usize, usize) { (a.min(b), a.max(b)) };
    let triangles: Vec<[(usize, usize); 3]> = match (ins.len(), outs.len()) {
        (1, 3) => vec![[0, 1, 2].map(|k| crossing(ins[0], outs[k]))],
        (3, 1) => vec![[0, 1, 2].map(|k| crossing(outs[0], ins[k]))],
        (2, 2) => {
            let quad = [
                crossing(ins[0], outs[0]),
                crossing(ins[0], outs[1]),
                crossing(ins[1], outs[1]),
                crossing(ins[1], outs[0]),
            ];
            vec![[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]]
        }
        _ => Vec::new(),
    };
    let p = |i: usize| corners[i].map(|c| c as f64);
    let mean = |of: &[usize]| {
        let n = of.len() as f64;
        std::array::from_fn::<f64, 3, _>(|k| of.iter().map(|&i| p(i)[k]).sum::<f64>() / n)
    };
    let (o, i) = (mean(&outs), mean(&ins));
    let outward: [f64; 3] = std::array::from_fn(|k| o[k] - i[k]);
    triangles
        .into_iter()
        .map(|t| {
            let m = t.map(|(a, b)| std::array::from_fn::<f64, 3, _>(|k| p(a)[k] + p(b)[k]));
            let d1: [f64; 3] = std::array::from_fn(|k| m[1][k] - m[0][k]);
            let d2: [f64; 3] = std::array::from_fn(|k| m[2][k] - m[0][k]);
            let normal = [
                d1[1] * d2[2] - d1[2] * d2[1],
                d1[2] * d2[0] - d1[0] * d2[2],
                d1[0] * d2[1] - d1[1] * d2[0],
            ];
            let facing: f64 = (0..3).map(|k| normal[k] * outward[k]).sum();
            if facing < 0.0 { [t[0], t[2], t[1]] } else { t }
        })
        .collect()
}
