//! The `seashells` command line: files are written for good input; every kind of bad input
//! gets exactly one line on stderr and a non-zero exit.

use crate::common;

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_seashells"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn temp(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("seashells-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name).to_string_lossy().into_owned()
}

#[test]
fn mesh_writes_each_format_by_extension() {
    for (ext, magic) in [
        ("glb", &b"glTF"[..]),
        ("ply", b"ply\n"),
        ("3mf", b"PK\x03\x04"),
        ("obj", b"# seashells"),
        ("stl", b"seashells"),
    ] {
        let out = temp(&format!("shell.{ext}"));
        let result = run(&["mesh", "--preset", "turbinate", "--out", &out]);
        assert!(
            result.status.success(),
            "{}",
            String::from_utf8_lossy(&result.stderr)
        );
        let bytes = std::fs::read(&out).unwrap();
        assert!(bytes.starts_with(magic), "{ext} file starts wrongly");
    }
}

#[test]
fn a_chamber_horn_exports_as_a_watertight_stl() {
    let out = temp("horn.stl");
    let result = run(&["mesh", "--preset", "kawaguchi-horn", "--out", &out]);
    assert!(
        result.status.success(),
        "{}",
        String::from_utf8_lossy(&result.stderr)
    );
    let count = common::watertight_stl_triangles(&std::fs::read(&out).unwrap());
    assert!(count > 1000, "{count} triangles");
}

#[test]
fn a_coral_exports_as_a_watertight_stl_of_closed_tubes() {
    let out = temp("coral.stl");
    let result = run(&["mesh", "--preset", "kawaguchi-coral", "--out", &out]);
    let said = String::from_utf8_lossy(&result.stdout);
    assert!(
        result.status.success() && said.contains("triangles"),
        "{said}"
    );
    let count = common::watertight_stl_triangles(&std::fs::read(&out).unwrap());
    assert!(count > 10_000, "{count} triangles");
}

#[test]
fn an_implicit_whorl_exports_as_a_watertight_stl_at_the_resolution_asked() {
    let coarse = temp("whorl-48.stl");
    let fine = temp("whorl.stl");
    let said = |args: &[&str]| {
        let result = run(args);
        assert!(
            result.status.success(),
            "{}",
            String::from_utf8_lossy(&result.stderr)
        );
        String::from_utf8_lossy(&result.stdout).into_owned()
    };
    said(&[
        "mesh",
        "--preset",
        "implicit-whorl",
        "--resolution",
        "48",
        "--out",
        &coarse,
    ]);
    said(&["mesh", "--preset", "implicit-whorl", "--out", &fine]);
    let n48 = common::watertight_stl_triangles(&std::fs::read(&coarse).unwrap());
    let n96 = common::watertight_stl_triangles(&std::fs::read(&fine).unwrap());
    // Triangles grow with the square of the resolution.
    assert!(n96 > 3 * n48 && n48 > 10_000, "{n48} then {n96}");
}

/// Rule 8 stops a branch under one pixel of the picture: a branching form exported for a
/// picture of more pixels grows finer tips, so more trunks.
#[test]
fn a_branching_form_exported_at_more_pixels_grows_further() {
    let triangles = |pixels: &str| {
        let out = temp(&format!("tendril-{pixels}.stl"));
        let result = run(&[
            "mesh",
            "--preset",
            "kawaguchi-tendril",
            "--resolution",
            pixels,
            "--out",
            &out,
        ]);
        assert!(
            result.status.success(),
            "{}",
            String::from_utf8_lossy(&result.stderr)
        );
        common::watertight_stl_triangles(&std::fs::read(&out).unwrap())
    };
    let (small, large) = (triangles("128"), triangles("2048"));
    assert!(large > small + small / 4, "{small} then {large}");
}

#[test]
fn mesh_takes_a_link_in_place_of_a_preset() {
    let out = temp("linked.stl");
    let result = run(&[
        "mesh",
        "--link",
        "#v=1&preset=turbinate&form.spiral.whorls=2",
        "--out",
        &out,
    ]);
    assert!(result.status.success());
    let small = std::fs::metadata(&out).unwrap().len();
    let full = temp("full.stl");
    assert!(
        run(&["mesh", "--preset", "turbinate", "--out", &full])
            .status
            .success()
    );
    assert!(
        small < std::fs::metadata(&full).unwrap().len() / 2,
        "two whorls make a smaller mesh"
    );
}

#[test]
fn a_murex_meshed_on_one_two_or_five_threads_is_the_same_file_and_bad_counts_are_refused() {
    let file = |threads: &str| {
        let path = temp(&format!("threads-{threads}.ply"));
        let out = run(&[
            "mesh",
            "--preset",
            "murex-cabritii",
            "--resolution",
            "64",
            "--threads",
            threads,
            "--out",
            &path,
        ]);
        assert!(out.status.success(), "{threads} threads: {out:?}");
        (std::fs::read(&path).unwrap(), out.stdout)
    };
    // The shell's last pieces fall in many groups, so that several threads share them.
    let decoded =
        seashells_core::share::link::decode("v=1&preset=murex-cabritii&form.resolution=64");
    let mut grown = seashells_core::generator::Generator::new(&decoded.spec).unwrap();
    let groups = grown.finish_apart().map_or(0, |pieces| pieces.groups.len());
    assert!(groups >= 10, "{groups} groups of pieces");
    let (one, said) = file("1");
    assert!(one.len() > 1_000_000, "{} bytes", one.len());
    for threads in ["2", "5"] {
        let (made, report) = file(threads);
        assert!(made == one, "{threads} threads wrote another file");
        assert_eq!(
            String::from_utf8_lossy(&report).replace(&format!("threads-{threads}"), "threads-1"),
            String::from_utf8_lossy(&said),
            "{threads} threads"
        );
    }
    for bad in ["0", "many", "65"] {
        let out = run(&["info", "--preset", "murex-cabritii", "--threads", bad]);
        assert_eq!(out.status.code(), Some(2), "--threads {bad}");
        let said = String::from_utf8_lossy(&out.stderr);
        assert!(
            said.contains(&format!(
                "--threads takes a whole number from 1 to 64, not '{bad}'"
            )),
            "{said}"
        );
    }
}

#[test]
fn bad_input_gets_one_line_and_a_non_zero_exit() {
    let out = temp("bad.stl");
    let cases: &[&[&str]] = &[
        &["mesh", "--preset", "no-such-shell", "--out", &out],
        &["mesh", "--preset", "turbinate", "--out", "shell.xyz"],
        &[
            "mesh",
            "--link",
            "v=1&preset=turbinate&form.spiral.whorls=lots",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--preset",
            "turbinate",
            "--link",
            "v=1&preset=turbinate",
            "--out",
            &out,
        ],
        &["mesh", "--preset", "turbinate"],
        &[
            "mesh",
            "--preset",
            "turbinate",
            "--out",
            "/no/such/folder/shell.stl",
        ],
        &[
            "mesh",
            "--link",
            "v=1&preset=kawaguchi-horn&form.mouth.protuberances=0,-3",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--link",
            "v=1&preset=kawaguchi-coral&form.knot.k0=40",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--preset",
            "implicit-whorl",
            "--resolution",
            "1000",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--preset",
            "turbinate",
            "--resolution",
            "64",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--link",
            "v=1&preset=implicit-whorl&form.generator.points=0,0,0,-0.5",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--link",
            "v=1&preset=implicit-canal-whorl&form.generator.pairs=0,3",
            "--out",
            &out,
        ],
        &[
            "mesh",
            "--link",
            "v=1&preset=implicit-whorl&form.generator.exponent=0",
            "--out",
            &out,
        ],
        &["mesh", "--colour", "red"],
        &["grow"],
        &[],
    ];
    for args in cases {
        let result = run(args);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(!result.status.success(), "{args:?} succeeded");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.starts_with("seashells: "), "{args:?}: {stderr}");
    }
}

#[test]
fn exports_that_cannot_be_made_say_why_and_leave_no_file() {
    let glb = temp("refused.glb");
    let printed = temp("refused.3mf");
    let stl = temp("refused.stl");
    let diverging = "v=1&preset=oliva-porphyria&pattern.model.kappa=0&pattern.model.rho=5";
    let cases: &[(&[&str], &str)] = &[
        (
            &["mesh", "--link", diverging, "--out", &glb],
            "stopped growing",
        ),
        (
            &[
                "mesh",
                "--link",
                "v=1&preset=turbinate&form.wall.thickness=0",
                "--out",
                &printed,
            ],
            "form.wall.thickness",
        ),
        (
            &[
                "mesh",
                "--preset",
                "turbinate",
                "--size",
                "0",
                "--out",
                &printed,
            ],
            "--size: 0 mm",
        ),
        (
            &[
                "mesh",
                "--preset",
                "turbinate",
                "--size",
                "2000",
                "--out",
                &glb,
            ],
            "--size: 2000 mm",
        ),
        (
            &[
                "mesh",
                "--preset",
                "turbinate",
                "--size",
                "tall",
                "--out",
                &glb,
            ],
            "--size",
        ),
        (
            &[
                "mesh",
                "--preset",
                "turbinate",
                "--size",
                "80",
                "--out",
                &stl,
            ],
            "--size",
        ),
    ];
    for (args, named) in cases {
        let result = run(args);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(!result.status.success(), "{args:?} succeeded");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains(named), "{args:?}: {stderr}");
    }
    for path in [&glb, &printed, &stl] {
        assert!(!std::path::Path::new(path).exists(), "{path} was written");
    }
}

#[test]
fn a_link_that_would_make_an_implicit_shell_empty_is_refused_naming_its_key() {
    // Each of these once grew to nothing: exit 0 and a file with no triangles. The message
    // names the key and the value as the link wrote it.
    for (link, key, value) in [
        (
            "v=1&preset=murex-cabritii&form.spiral.r0=1e-300",
            "form.spiral.r0",
            "1e-300",
        ),
        (
            "v=1&preset=murex-cabritii&form.generator.points=0,0,0,1e300",
            "form.generator.points",
            "1e300",
        ),
        (
            "v=1&preset=implicit-whorl&form.generator.points=0,0,0,1e-300",
            "form.generator.points",
            "1e-300",
        ),
        (
            "v=1&preset=murex-cabritii&form.opening.inside.points=1e300,0,0,0.6",
            "form.opening.inside.points",
            "1e300",
        ),
    ] {
        let out = temp("empty.stl");
        let _ = std::fs::remove_file(&out);
        let result = run(&["mesh", "--link", link, "--out", &out]);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(!result.status.success(), "{link} succeeded");
        assert!(stderr.contains(key), "{link}: {stderr}");
        assert!(stderr.contains(value), "{link}: {stderr}");
        assert!(!std::path::Path::new(&out).exists(), "{link} wrote a file");
    }
}

#[test]
fn help_is_asked_for_in_every_usual_way_and_a_refusal_is_exit_status_2() {
    for args in [&["--help"][..], &["-h"], &["help"]] {
        let out = run(args);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{args:?}");
        assert!(
            text.contains("seashells mesh") && text.contains("Exit status"),
            "{args:?}: {text}"
        );
    }
    for args in [&["help", "mesh"][..], &["mesh", "--help"]] {
        let out = run(args);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{args:?}");
        assert!(text.contains("--resolution N"), "{args:?}: {text}");
    }
    let out = run(&["help", "grow"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no command 'grow'"));
}

/// `seashells mesh` of the link to `preset` and its changes `link` (as "ID&key=value…").
fn mesh_of(link: &str, path: &str) -> Output {
    run(&[
        "mesh",
        "--link",
        &format!("v=1&preset={link}"),
        "--out",
        path,
    ])
}

/// The links that once made bad files with exit status 0 (NaN or infinite coordinates, float32
/// losing faces, whorls lying on one another, an ammonite passing through itself): each is
/// refused naming its key and no file is written, or it makes a closed solid of finite
/// coordinates.
#[test]
fn the_links_that_made_bad_files_are_refused_naming_the_key_or_make_a_solid() {
    let refused = [
        (
            "kawaguchi-horn&form.chamber.ratio=0.5&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 0.5 shrink the last to 10^-602 of the first: at most 13 at this ratio",
        ),
        (
            "kawaguchi-horn&form.chamber.ratio=2&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 2 grow",
        ),
        (
            "kawaguchi-tusk&form.chamber.ratio=1.5&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 1.5 grow the last to 10^352 times the first: at most 22",
        ),
        (
            "kawaguchi-tusk&form.chamber.ratio=2&form.chambers=2000",
            "at most 13 at this ratio",
        ),
        (
            "kawaguchi-ammonite&form.chamber.ratio=2&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 2",
        ),
        (
            "kawaguchi-ammonite&form.chamber.ratio=0.5&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 0.5",
        ),
        (
            "kawaguchi-claw&form.chamber.ratio=0.5&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 0.5",
        ),
        (
            "kawaguchi-shell&form.chambers=2000",
            "form.chambers: 2000 chambers at ratio 1.035 grow the last to 10^30 times the first: at most 267",
        ),
        (
            "kawaguchi-painted&form.chambers=2000",
            "at most 533 at this ratio",
        ),
        (
            "kawaguchi-ammonite&form.chamber.ratio=1.0",
            "form.chamber.ratio: whorls overlap: each chamber passes through the one 24 chambers later",
        ),
        (
            "kawaguchi-ammonite&form.chamber.ratio=1.036",
            "form.chamber.ratio: whorls overlap",
        ),
    ];
    for (link, said) in refused {
        let path = temp("refused-link.3mf");
        let _ = std::fs::remove_file(&path);
        let out = mesh_of(link, &path);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{link}: {stderr}");
        assert!(stderr.contains(said), "{link}: {stderr}");
        assert!(!std::path::Path::new(&path).exists(), "{link} wrote a file");
    }
    for link in [
        "kawaguchi-ammonite",
        "kawaguchi-tusk&form.chambers=2000&form.chamber.ratio=1.002",
        "kawaguchi-horn&form.chambers=270&form.chamber.ratio=1.0345",
    ] {
        let path = temp("solid-link.stl");
        let out = mesh_of(link, &path);
        assert!(
            out.status.success(),
            "{link}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let bytes = std::fs::read(&path).unwrap();
        assert!(common::watertight_stl_triangles(&bytes) > 1000, "{link}");
        let finite = bytes[84..].chunks_exact(50).all(|t| {
            t[0..48]
                .chunks_exact(4)
                .all(|f| f32::from_le_bytes(f.try_into().unwrap()).is_finite())
        });
        assert!(finite, "{link}: a coordinate is not finite");
    }
}

#[test]
fn a_file_written_to_standard_output_is_the_file_written_to_a_path() {
    let path = temp("to-path.stl");
    let to_path = run(&["mesh", "--preset", "kawaguchi-horn", "--out", &path]);
    assert!(to_path.status.success());
    let to_stdout = run(&[
        "mesh",
        "--preset",
        "kawaguchi-horn",
        "--out",
        "-",
        "--format",
        "stl",
    ]);
    assert!(to_stdout.status.success());
    assert_eq!(to_stdout.stdout, std::fs::read(&path).unwrap());
    // The report goes to standard error, out of the file's way.
    assert!(String::from_utf8_lossy(&to_stdout.stderr).starts_with("wrote -: "));
    let png = run(&[
        "pattern",
        "--preset",
        "oliva-porphyria",
        "--out",
        "-",
        "--format",
        "png",
    ]);
    assert!(png.stdout.starts_with(b"\x89PNG"));
    let unnamed = run(&["mesh", "--preset", "kawaguchi-horn", "--out", "-"]);
    assert_eq!(unnamed.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&unnamed.stderr).contains("--out - needs --format"));
}

#[test]
fn a_file_that_cannot_be_written_is_exit_status_1_and_a_refusal_2() {
    let failed = run(&[
        "mesh",
        "--preset",
        "kawaguchi-horn",
        "--out",
        "/no/such/folder/horn.stl",
    ]);
    assert_eq!(failed.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&failed.stderr).contains("cannot write '/no/such/folder/horn.stl'")
    );
    let refused = run(&["mesh", "--preset", "kawaguchi-horn", "--out", "horn.xyz"]);
    assert_eq!(refused.status.code(), Some(2));
}

#[test]
fn a_link_the_page_opens_the_command_line_opens_saying_what_it_read() {
    // A link of the retired reading of T: the page opens it with a note, and so does this.
    let link = "v=1&preset=kawaguchi-shell&form.chamber.translation.x=0.1&form.chamber.translation.y=0.2&form.chamber.translation.z=0.15";
    let path = temp("retired.stl");
    let out = run(&["mesh", "--link", link, "--out", &path]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.starts_with("seashells: note: form.chamber.translation: links made before T became the top base's position"),
        "{stderr}"
    );
    // A whole address is read by its fragment.
    let whole = run(&["info", "http://127.0.0.1:8000/#v=1&preset=kawaguchi-horn"]);
    assert!(whole.status.success());
    assert!(
        String::from_utf8_lossy(&whole.stdout).starts_with("shell: kawaguchi-horn (Ram's horn)")
    );
}

#[test]
fn info_says_the_shells_counts_its_size_and_the_files_it_makes() {
    let out = run(&["info", "v=1&preset=kawaguchi-tusk"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    // The same counts and bytes as the files themselves.
    let path = temp("info-tusk.stl");
    let mesh = run(&["mesh", "--preset", "kawaguchi-tusk", "--out", &path]);
    let wrote = String::from_utf8_lossy(&mesh.stdout);
    let counts = wrote
        .split(": ")
        .nth(1)
        .unwrap()
        .split(", hash")
        .next()
        .unwrap();
    assert!(text.contains(counts), "{text} lacks {counts}");
    let bytes = std::fs::metadata(&path).unwrap().len();
    assert!(
        text.lines()
            .any(|l| l.contains("kawaguchi-tusk.stl") && l.ends_with(&format!(" {bytes} bytes"))),
        "{text}"
    );
    // The tusk lies long: 80 mm is its length, and it stands far lower.
    let size = text
        .lines()
        .find(|l| l.starts_with("size: "))
        .expect("a size line");
    let sides: Vec<f64> = size["size: ".len()..]
        .split(" mm")
        .next()
        .unwrap()
        .split(" × ")
        .map(|s| s.parse().unwrap())
        .collect();
    assert_eq!(sides.iter().cloned().fold(0.0, f64::max), 80.0, "{size}");
    assert!(sides[2] < 20.0, "{size}");
    let refused = run(&["info", "v=1&preset=turbinate&form.wall.thickness=0"]);
    let text = String::from_utf8_lossy(&refused.stdout);
    assert!(
        text.lines()
            .any(|l| l.contains("turbinate.3mf") && l.contains("refused: 3MF holds closed solids")),
        "{text}"
    );
}
