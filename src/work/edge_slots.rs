//! Where a host puts each part of its growing shell's edge in the page's slotted copy
//! ([`SlottedEdge`]), and what it sends for each new edge: nothing for a part that is as the
//! page holds it, a part rewritten in its slot when it still fits there, moved to a new slot
//! (the old one's indices zeroed) when it has outgrown it. Each slot has room to spare, so that
//! a part re-meshed a little larger stays in place; freed room is joined to its free
//! neighbours and taken again first come first served, and when gaps make up more than half of
//! the mesh, every part is laid out anew from the start.

use super::slotted_edge::{EdgeRun, EdgeWrites, Slot, SlottedEdge, range};
use crate::mesh::{Mesh, Vertex};
use crate::shape::EdgePart;
use std::collections::BTreeMap;
use std::ops::Range;

/// Gaps the slotted mesh may hold beyond as much again as its parts, in vertices or indices,
/// before it is laid out anew.
const LOOSE: u32 = 4096;

/// The room a part of `n` vertices or indices is given: an eighth more, and a little, in whole
/// triangles, so that every slot's indices start on a triangle of the one draw of the mesh.
fn with_spare(n: u32) -> u32 {
    (n + n / 8 + 16).next_multiple_of(3)
}

/// Runs of free room in one of the slotted mesh's arrays (start → end, neighbours joined),
/// and where its used room ends.
#[derive(Default)]
struct Room {
    free: BTreeMap<u32, u32>,
    end: u32,
}

impl Room {
    /// The first free run of `n` that fits, or room at the end.
    fn take(&mut self, n: u32) -> Range<u32> {
        let found = (self.free.iter()).find(|&(&start, &end)| end - start >= n);
        if let Some((&start, &end)) = found {
            self.free.remove(&start);
            if start + n < end {
                self.free.insert(start + n, end);
            }
            return start..start + n;
        }
        self.end += n;
        self.end - n..self.end
    }

    /// Frees `run`, joined to the free runs beside it; free room at the end is no longer used.
    fn give_back(&mut self, run: Range<u32>) {
        let (mut start, mut end) = (run.start, run.end);
        if let Some((&before, &before_end)) = self.free.range(..start).next_back()
            && before_end == start
        {
            self.free.remove(&before);
            start = before;
        }
        if let Some(after_end) = self.free.remove(&end) {
            end = after_end;
        }
        if end == self.end {
            self.end = start;
        } else if start < end {
            self.free.insert(start, end);
        }
    }
}

/// A part's room in both arrays.
#[derive(Clone)]
struct Place {
    vertices: Range<u32>,
    indices: Range<u32>,
}

/// What a host knows of the edge the page holds, and where there is room in it.
#[derive(Default)]
pub(crate) struct EdgeSlots {
    held: SlottedEdge,
    places: BTreeMap<u32, Place>,
    vertices: Room,
    indices: Room,
}

impl EdgeSlots {
    /// What turns the edge the page holds into `edge`, whose parts are `parts` (in the order of
    /// their numbers); from now on the page is taken to hold it.
    pub(crate) fn update(&mut self, edge: &Mesh, parts: &[EdgePart]) -> EdgeWrites {
        let parts: Vec<&EdgePart> = parts.iter().filter(|p| !p.indices.is_empty()).collect();
        let mut writes = self.place(edge, &parts);
        let used = |r: fn(&EdgePart) -> usize| parts.iter().map(|&p| r(p)).sum::<usize>() as u32;
        let (vertices, indices) = (used(|p| p.vertices.len()), used(|p| p.indices.len()));
        let loose = |end: u32, used: u32| end > 2 * used + LOOSE;
        if indices == 0 || loose(self.vertices.end, vertices) || loose(self.indices.end, indices) {
            *self = Self::default();
            writes = self.place(edge, &parts);
        }
        self.held.apply(&writes);
        writes
    }

    /// The writes that put `parts` of `edge` in place, each in the room it has or in new room.
    fn place(&mut self, edge: &Mesh, parts: &[&EdgePart]) -> EdgeWrites {
        let fresh = self.held.mesh().vertices.is_empty() && self.held.mesh().indices.is_empty();
        let mut runs = Vec::new();
        let gone: Vec<u32> = (self.places.keys())
            .filter(|id| parts.binary_search_by_key(id, |p| &p.id).is_err())
            .copied()
            .collect();
        for id in gone {
            self.free(id, &mut runs);
        }
        let mut slots = Vec::with_capacity(parts.len());
        for &part in parts {
            let (nv, ni) = (part.vertices.len() as u32, part.indices.len() as u32);
            let held = self.held_slot(part.id);
            let fits = (self.places.get(&part.id))
                .filter(|place| {
                    nv <= place.vertices.len() as u32 && ni <= place.indices.len() as u32
                })
                .cloned();
            let slot = match (fits, held) {
                (Some(place), Some(held)) => {
                    let slot = Slot {
                        id: part.id,
                        vertices: place.vertices.start..place.vertices.start + nv,
                        indices: place.indices.start..place.indices.start + ni,
                    };
                    if !self.holds(edge, part, &held) {
                        let mut run = self.run(edge, part, &slot);
                        // Zero what the part held beyond its new end.
                        let beyond = held.indices.end.saturating_sub(slot.indices.end);
                        run.indices.extend(std::iter::repeat_n(0, beyond as usize));
                        runs.push(run);
                    }
                    slot
                }
                _ => {
                    if self.places.contains_key(&part.id) {
                        self.free(part.id, &mut runs);
                    }
                    let place = Place {
                        vertices: self.vertices.take(with_spare(nv)),
                        indices: self.indices.take(with_spare(ni)),
                    };
                    let slot = Slot {
                        id: part.id,
                        vertices: place.vertices.start..place.vertices.start + nv,
                        indices: place.indices.start..place.indices.start + ni,
                    };
                    // The whole room is written, spare included, so that nothing the page
                    // draws was never written.
                    let mut run = self.run(edge, part, &slot);
                    (run.vertices).resize(place.vertices.len(), Vertex::default());
                    run.indices.resize(place.indices.len(), 0);
                    runs.push(run);
                    self.places.insert(part.id, place);
                    slot
                }
            };
            slots.push(slot);
        }
        // Zeros over room freed at the end, which is no longer held, are not sent.
        for run in &mut runs {
            let room = self.indices.end.saturating_sub(run.first_index) as usize;
            run.indices.truncate(room);
        }
        runs.retain(|run| !run.vertices.is_empty() || !run.indices.is_empty());
        EdgeWrites {
            fresh,
            vertex_count: self.vertices.end,
            index_count: self.indices.end,
            slots,
            runs,
        }
    }

    /// Frees part `id`'s room, zeroing the indices it held.
    fn free(&mut self, id: u32, runs: &mut Vec<EdgeRun>) {
        let place = self.places.remove(&id).expect("a part with a place");
        if let Some(held) = self.held_slot(id) {
            runs.push(EdgeRun {
                first_index: held.indices.start,
                indices: vec![0; held.indices.len()],
                ..EdgeRun::default()
            });
        }
        self.vertices.give_back(place.vertices);
        self.indices.give_back(place.indices);
    }

    /// Where the page holds part `id`, if it does.
    fn held_slot(&self, id: u32) -> Option<Slot> {
        let slots = self.held.slots();
        (slots.binary_search_by_key(&id, |s| s.id).ok()).map(|k| slots[k].clone())
    }

    /// Whether the page holds `part` of `edge` as it is, in `slot`.
    fn holds(&self, edge: &Mesh, part: &EdgePart, slot: &Slot) -> bool {
        let mesh = self.held.mesh();
        fn bytes(v: &[Vertex]) -> &[u8] {
            bytemuck::cast_slice(v)
        }
        slot.vertices.len() == part.vertices.len()
            && slot.indices.len() == part.indices.len()
            && bytes(&mesh.vertices[range(&slot.vertices)])
                == bytes(&edge.vertices[part.vertices.clone()])
            && (mesh.indices[range(&slot.indices)].iter())
                .zip(&edge.indices[part.indices.clone()])
                .all(|(&held, &i)| held - slot.vertices.start == i - part.vertices.start as u32)
    }

    /// `part` of `edge` written in `slot`, its indices naming the slot's vertices.
    fn run(&self, edge: &Mesh, part: &EdgePart, slot: &Slot) -> EdgeRun {
        let shift = |i: &u32| i - part.vertices.start as u32 + slot.vertices.start;
        EdgeRun {
            first_vertex: slot.vertices.start,
            vertices: edge.vertices[part.vertices.clone()].to_vec(),
            first_index: slot.indices.start,
            indices: edge.indices[part.indices.clone()]
                .iter()
                .map(shift)
                .collect(),
        }
    }
}

#[cfg(all(test, not(target_arch = "wasm32")))]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// An edge of parts numbered by the keys of `parts`, each (vertices, triangles, version):
    /// a part's content follows from its number and version alone.
    fn edge_of(parts: &BTreeMap<u32, (u32, u32, u32)>) -> (Mesh, Vec<EdgePart>) {
        let mut edge = Mesh::default();
        let mut layout = Vec::new();
        for (&id, &(nv, nt, version)) in parts {
            let (v0, i0) = (edge.vertices.len(), edge.indices.len());
            for k in 0..nv {
                edge.vertices.push(Vertex {
                    position: [id as f32, version as f32, k as f32],
                    ..Vertex::default()
                });
            }
            for t in 0..nt * 3 {
                edge.indices.push(v0 as u32 + (t * 7 + version) % nv);
            }
            layout.push(EdgePart {
                id,
                vertices: v0..edge.vertices.len(),
                indices: i0..edge.indices.len(),
            });
        }
        (edge, layout)
    }

    /// A part's number, and its new (vertices, triangles) or none when it goes.
    type Change = (u32, Option<(u32, u32)>);

    /// Steps of an edge's growth: which parts change (a new version and size) or go.
    fn steps() -> impl Strategy<Value = Vec<Vec<Change>>> {
        let change = (
            0u32..40,
            prop::option::weighted(0.8, (1u32..300, 1u32..200)),
        );
        prop::collection::vec(prop::collection::vec(change, 0..12), 1..40)
    }

    proptest! {
        #[test]
        fn the_page_holds_the_edge_and_takes_only_what_changed(steps in steps()) {
            let mut slots = EdgeSlots::default();
            let mut page = SlottedEdge::default();
            let mut parts = BTreeMap::new();
            for (version, step) in steps.iter().enumerate() {
                let before = parts.clone();
                for &(id, change) in step {
                    match change {
                        Some((nv, nt)) => parts.insert(id, (nv, nt, version as u32)),
                        None => parts.remove(&id),
                    };
                }
                let (edge, layout) = edge_of(&parts);
                let writes = slots.update(&edge, &layout);
                let runs = page.apply(&writes);
                prop_assert_eq!(&page, &slots.held);
                prop_assert_eq!(page.joined(), edge.clone());
                // Nothing outside a slot draws; each slot's indices name its own vertices.
                let mesh = page.mesh();
                let mut inside = vec![false; mesh.indices.len()];
                for slot in page.slots() {
                    inside[range(&slot.indices)].fill(true);
                    prop_assert!(mesh.indices[range(&slot.indices)]
                        .iter()
                        .all(|i| slot.vertices.contains(i)));
                }
                prop_assert!(mesh.indices.iter().zip(&inside).all(|(&i, &s)| s || i == 0));
                // One draw of the slotted mesh draws the edge's triangles, and only those.
                let triangles = |m: &Mesh| {
                    let mut t: Vec<[[u32; 3]; 3]> = (m.indices.chunks(3))
                        .filter(|t| t[0] != t[1] || t[1] != t[2])
                        .map(|t| [t[0], t[1], t[2]].map(|i| m.vertices[i as usize].position.map(f32::to_bits)))
                        .collect();
                    t.sort();
                    t
                };
                prop_assert_eq!(triangles(mesh), triangles(&edge));
                // The gaps stay within bounds.
                let used = edge.vertices.len() as u32;
                prop_assert!(writes.vertex_count <= 2 * used + LOOSE);
                // A part as it was is not written again, unless all is laid out anew.
                if !writes.fresh {
                    for slot in page.slots().iter().filter(|s| before.get(&s.id) == parts.get(&s.id)) {
                        let touched = |r: &Range<usize>| {
                            r.start < slot.indices.end as usize && slot.indices.start as usize <= r.end.saturating_sub(1)
                        };
                        prop_assert!(!runs.indices.iter().any(touched), "part {} written again", slot.id);
                    }
                }
            }
        }
    }
}
