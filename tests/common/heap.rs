//! The heap a thread holds, counted by the test binary's global allocator: every allocation
//! adds its size to the allocating thread's count, every release takes it off the releasing
//! thread's, and each thread keeps the highest count it reached. A test that measures meshes
//! on its own thread, so what other tests hold at the time is not counted. A reallocation
//! counts as the change of size: a model of the large buffers of a mesh, whose pages glibc
//! moves (`mremap`) instead of copying, so that the old and the new are never held at once.
//! Below its threshold for mapping (128 KB to 32 MB, as it adapts) a buffer may be copied, and
//! for that moment both are held; the counts leave that moment out.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting.
pub struct Counting;

thread_local! {
    static HELD: Cell<isize> = const { Cell::new(0) };
    static PEAK: Cell<isize> = const { Cell::new(0) };
}

fn count(change: isize) {
    // `try_with`: a thread being torn down has no counts left, and is not measured.
    let _ = HELD.try_with(|held| {
        let now = held.get() + change;
        held.set(now);
        let _ = PEAK.try_with(|peak| peak.set(peak.get().max(now)));
    });
}

// SAFETY: every call is passed on to `System` unchanged; the counts only read sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            count(layout.size() as isize);
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            count(layout.size() as isize);
        }
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        unsafe { System.dealloc(p, layout) };
        count(-(layout.size() as isize));
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, size: usize) -> *mut u8 {
        let q = unsafe { System.realloc(p, layout, size) };
        if !q.is_null() {
            count(size as isize - layout.size() as isize);
        }
        q
    }
}

/// What `f` returns, and the most heap the calling thread held beyond what it held before
/// while `f` ran, in bytes.
/// Calls may nest: the outer one still counts what the inner one saw.
pub fn peak_of<T>(f: impl FnOnce() -> T) -> (T, usize) {
    let before = HELD.with(Cell::get);
    let outer = PEAK.with(|peak| peak.replace(before));
    let out = f();
    let peak = PEAK.with(|p| p.replace(p.get().max(outer)));
    (out, (peak - before).max(0) as usize)
}
