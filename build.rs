//! Lists the presets in species/ for `include_str!`, so that a new file there is a new preset.
//!
//! The generated table names each file relative to the crate being compiled
//! (`concat!(env!("CARGO_MANIFEST_DIR"), …)`), never by this script's absolute path, so a
//! checkout moved or copied with its build cache reads its own files, and an edit to one is
//! seen by the compiler's own tracking of included files.

use std::fmt::Write;
use std::path::Path;

fn main() {
    let manifest = std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let dir = Path::new(&manifest).join("species");
    // Relative to the package: a new or removed file there lists the presets again.
    println!("cargo:rerun-if-changed=species");
    let mut ids: Vec<String> = std::fs::read_dir(&dir)
        .expect("species/ exists")
        .map(|e| e.expect("readable species/ entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .map(|p| {
            p.file_stem()
                .and_then(|s| s.to_str())
                .expect("UTF-8 file name")
                .to_string()
        })
        .collect();
    ids.sort();
    let mut out = String::from(
        "/// (id, JSON) of every file in species/.\npub const PRESET_FILES: &[(&str, &str)] = &[\n",
    );
    for id in ids {
        writeln!(
            out,
            "    ({id:?}, include_str!(concat!(env!(\"CARGO_MANIFEST_DIR\"), \"/species/{id}.json\"))),"
        )
        .expect("write to string");
    }
    out.push_str("];\n");
    let target =
        Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("species.rs");
    std::fs::write(target, out).expect("write species table");
}
