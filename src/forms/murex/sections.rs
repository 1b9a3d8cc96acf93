//! Instances of a generating surface blended into sections (eq 9), and sections combined by
//! blending or by controlled blending with their neighbours only (eq 10), with the boxes of
//! what each growth step adds or takes away.

use super::generating_surface::generating_surface;
use super::helix::Instances;
use crate::blobtree::blob_tree::Node;
use crate::mesh::Bounds;
use crate::spec::form::implicit::{Blending, GeneratorSpec};
use glam::{DAffine3, DVec3};

/// A BlobTree being gathered, with the boxes of what each growth step adds or takes away.
pub(crate) struct Gathered {
    pub(crate) reach: Vec<Vec<Bounds>>,
}

impl Gathered {
    /// `node`, placed at instance `at` and born at growth step `birth`.
    pub(crate) fn placed(&mut self, at: DAffine3, node: Node, birth: u32) -> Node {
        self.placed_living(at, node, birth, u32::MAX)
    }

    /// `node`, placed at instance `at`, born at growth step `birth` and gone from step
    /// `death` on: both steps change the shell where it stands.
    pub(crate) fn placed_living(
        &mut self,
        at: DAffine3,
        node: Node,
        birth: u32,
        death: u32,
    ) -> Node {
        let node = Node::transform(at, node).living(birth, death);
        for step in [birth, death] {
            if let Some(boxes) = self.reach.get_mut(step as usize) {
                boxes.push(node.bounds);
            }
        }
        node
    }
}

/// The generating surface `g` placed at the instances `scaled` gives (k, with the factor the
/// generating surface is scaled by about its centre) and blended into sections of `surfaces`
/// instances (eq 9), instance k joining section k / `surfaces` and born at growth step
/// k − `ahead` (or 0). Empty sections are left out.
pub(crate) fn sections(
    g: &GeneratorSpec,
    instances: &Instances,
    scaled: impl Iterator<Item = (u32, f64)>,
    surfaces: u32,
    ahead: u32,
    gathered: &mut Gathered,
) -> Vec<(u32, Node)> {
    let mut out: Vec<(u32, Vec<Node>)> = Vec::new();
    for (k, scale) in scaled {
        let kf = f64::from(k);
        // The hollow ahead of the edge shows the edge's pattern on its inside.
        let time = instances.time(kf.min(f64::from(instances.count - 1)));
        let Some(surface) = generating_surface(g, time, instances.whorl(kf)) else {
            continue;
        };
        let at = instances.placement(kf) * DAffine3::from_scale(DVec3::splat(scale));
        let placed = gathered.placed(at, surface, k.saturating_sub(ahead));
        let section = k / surfaces;
        match out.last_mut() {
            Some((s, members)) if *s == section => members.push(placed),
            _ => out.push((section, vec![placed])),
        }
    }
    out.into_iter()
        .map(|(s, members)| (s, Node::blend(members)))
        .collect()
}

/// Sections combined as the spec's blending says, with parts each paired with the sections
/// it names (eq 10: a part blends only with those).
pub(crate) fn joined(
    blending: Blending,
    sections: Vec<Node>,
    parts: Vec<(Node, Vec<usize>)>,
) -> Node {
    match blending {
        Blending::All => Node::blend(
            sections
                .into_iter()
                .chain(parts.into_iter().map(|p| p.0))
                .collect(),
        ),
        Blending::Neighbours => {
            let n = sections.len();
            let mut pairs: Vec<[usize; 2]> = (1..n).map(|i| [i - 1, i]).collect();
            let mut children = sections;
            for (part, with) in parts {
                let index = children.len();
                pairs.extend(with.into_iter().filter(|&s| s < n).map(|s| [s, index]));
                children.push(part);
            }
            Node::controlled(children, pairs)
        }
    }
}
