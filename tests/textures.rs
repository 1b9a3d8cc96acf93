//! Four textures blended by field (Galbraith, Prusinkiewicz & Wyvill §3.4, figs 12 and 14):
//! deep inside one part the colour is that part's texture; where parts blend it is their
//! colours weighted by their fields; the spines darken from base to tip; the spec's textures
//! travel in links, bad values are named; the same spec gives the same bits, and the exports
//! carry the blended colours.

use crate::common;

use common::{assert_refused_and_repaired, implicit};
use glam::DVec3;
use seashells_core::blobtree::blob_tree::Node;
use seashells_core::blobtree::falloff::support_of;
use seashells_core::blobtree::image_map::ImageMap;
use seashells_core::blobtree::primitive::Primitive;
use seashells_core::blobtree::texture_blend::{Look, MapOn, Texture};
use seashells_core::export::MeshFormat;
use seashells_core::export::job::Export;
use seashells_core::export::paint::Paint;
use seashells_core::export::print_size::PrintSize;
use seashells_core::export::shell::Shell;
use seashells_core::forms::murex::check::check;
use seashells_core::forms::murex::fine_parts::FineParts;
use seashells_core::forms::murex::textures::look;
use seashells_core::forms::murex::varix::{Spine, Standing, outward, varix};
use seashells_core::generator::Generator;
use seashells_core::mesh::{Surface, Vertex};
use seashells_core::presets;
use seashells_core::share::link::{decode, encode};
use seashells_core::spec::ShellSpec;
use seashells_core::spec::form::textures::{ImageOf, PartTexture, TextureKind, TexturesSpec};
use seashells_core::spec::pattern::Model;
use serde_json::Value;

fn spec_of(id: &str) -> ShellSpec {
    presets::preset(id).expect(id).spec.clone()
}

fn grown(spec: &ShellSpec) -> Generator {
    let mut g = Generator::new(spec).expect("builds");
    g.finish();
    g
}

/// Relative luminance of a linear-light colour.
fn luminance(c: [f64; 3]) -> f64 {
    0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
}

#[test]
fn deep_in_a_part_its_own_texture_and_on_a_blend_the_field_weighted_colours() {
    let body = Primitive::Point {
        centre: DVec3::ZERO,
        radius: support_of(1.0),
    };
    let spine = Primitive::Cone {
        from: DVec3::X * 0.8,
        to: DVec3::X * 3.0,
        radii: [support_of(0.3), support_of(0.1)],
    };
    let (base, tip) = ([0.8, 0.7, 0.6], [0.1, 0.05, 0.02]);
    let ramp = Look::Ramp {
        base,
        tip,
        shade: 1.0,
        start: 0.0,
    };
    let tree = Node::blend(vec![
        Node::leaf(body.clone(), Texture::around(5.0)),
        Node::leaf(spine.clone(), Texture::around(9.0).looking(ramp)),
    ]);
    let along = |p: DVec3| ((p.x - 0.8) / 2.2).clamp(0.0, 1.0);
    let ramp_at = |p: DVec3| Look::ramp(base, tip, 1.0, 0.0, along(p));

    // Deep in the spine, where the body's field is zero: the spine's ramp alone.
    let p = DVec3::new(2.5, 0.05, 0.0);
    assert_eq!(body.field(p), 0.0);
    let [r, g, b, share] = tree.probe(p).paint.tint();
    let want = ramp_at(p);
    for (got, want) in [r, g, b].into_iter().zip(want) {
        assert!((got - want).abs() < 1e-12, "{got} {want}");
    }
    assert_eq!(share, 0.0);

    // Deep in the body: the pattern alone, at the body's coordinates.
    let p = DVec3::new(-1.5, 0.2, 0.0);
    assert_eq!(spine.field(p), 0.0);
    let probe = tree.probe(p);
    assert_eq!(probe.paint.tint(), [0.0, 0.0, 0.0, 1.0]);
    assert!((probe.paint.coordinates()[1] - 5.0).abs() < 1e-12);

    // Where they blend: each part's colour weighted by its field at the point.
    let p = DVec3::new(1.3, 0.1, 0.0);
    let (fb, fs) = (body.field(p), spine.field(p));
    assert!(fb > 0.05 && fs > 0.05, "{fb} {fs}");
    let probe = tree.probe(p);
    assert!((probe.field - (fb + fs)).abs() < 1e-12);
    let [r, g, b, share] = probe.paint.tint();
    let want = ramp_at(p).map(|c| c * fs / (fb + fs));
    for (got, want) in [r, g, b].into_iter().zip(want) {
        assert!((got - want).abs() < 1e-12, "{got} {want}");
    }
    assert!((share - fb / (fb + fs)).abs() < 1e-12);
    // The body's coordinates are not pulled towards the spine's: colours blend, not
    // coordinates.
    assert!((probe.paint.coordinates()[1] - 5.0).abs() < 1e-12);

    // The one colouring (page and exports) mixes the pattern (here the ground colour) by its
    // share and adds the ramp's colour, in linear light.
    let colours = spec_of("murex-cabritii").colours;
    let paint = Paint::new(&colours, None);
    let vertex = Vertex::new(p, DVec3::X, probe.paint.coordinates(), Surface::Outer)
        .tinted([r, g, b, share]);
    let ground = colours.ground.linear().map(f64::from);
    let expected: [f64; 3] = std::array::from_fn(|k| share * ground[k] + want[k]);
    let got = paint.colour(&vertex);
    let got_linear = paint.linear(got).map(f64::from);
    for k in 0..3 {
        assert!(
            (got_linear[k] - expected[k]).abs() < 0.01,
            "{got:?} vs {expected:?}"
        );
    }
}

#[test]
fn the_default_spines_darken_from_base_to_tip() {
    let mut spec = spec_of("murex-cabritii");
    let i = implicit(&mut spec);
    let mut varices = i.varices.clone();
    varices.bend = 0.0;
    varices.ridge = 0.0;
    let textures = *i.textures;
    assert_eq!(textures, TexturesSpec::default());
    let standing = Standing {
        spine: Spine {
            angle: 20.0,
            sigma: 1.0,
        },
        edge: 1.0,
    };
    // One spine on its own, with no grid to refine for and no floor to thicken it to.
    let spine = |textures: &TexturesSpec| {
        varix(
            &varices,
            &[standing],
            1.0,
            &mut FineParts::new(0.0, 0.0),
            0.0,
            &textures.spines,
            Look::Pattern,
        )
        .expect("a spine")
    };
    let tree = spine(&textures);
    let (length, base) = (varices.length, varices.radius);
    let direction = outward(20.0);
    let colours: Vec<[f64; 4]> = (1..20)
        .map(|k| {
            let s = f64::from(k) / 20.0;
            tree.probe(direction * (1.0 + s * (length - base)))
                .paint
                .tint()
        })
        .collect();
    for pair in colours.windows(2) {
        let [a, b] = [pair[0], pair[1]].map(|c| luminance([c[0], c[1], c[2]]));
        assert!(b < a, "{colours:?}");
    }
    let first = luminance([colours[0][0], colours[0][1], colours[0][2]]);
    let last = colours.last().unwrap();
    let last = luminance([last[0], last[1], last[2]]);
    assert!(last < 0.3 * first, "{first} → {last}");
    // A spine shows its ramp only, not the pattern's spiral lines.
    assert!(colours.iter().all(|c| c[3] == 0.0));
    // With the pattern chosen instead, the spine shows the pattern.
    let mut patterned = textures;
    patterned.spines.look = TextureKind::Pattern;
    let tree = spine(&patterned);
    assert_eq!(
        tree.probe(direction * 1.5).paint.tint(),
        [0.0, 0.0, 0.0, 1.0]
    );
    assert_eq!(
        look(&patterned.spines, MapOn::Part { start: 0.2 }),
        Look::Pattern
    );
}

#[test]
fn the_grown_murex_wears_four_textures_and_the_exports_carry_them() {
    let mut spec = spec_of("murex-cabritii");
    implicit(&mut spec).resolution = 64;
    let g = grown(&spec);
    let mesh = g.snapshot();
    let outer: Vec<&Vertex> = mesh.vertices.iter().filter(|v| v.is_outer()).collect();
    let pure_part = outer.iter().filter(|v| v.tint[3] == 0.0).count();
    let pure_body = outer.iter().filter(|v| v.tint[3] == 1.0).count();
    let blended = outer.len() - pure_part - pure_body;
    assert!(
        pure_part > outer.len() / 50 && pure_body > outer.len() / 4 && blended > 100,
        "{pure_part} part, {pure_body} body, {blended} blended of {}",
        outer.len()
    );
    assert!(Paint::tinted(&mesh.vertices));

    let preset = presets::preset("murex-cabritii").unwrap();
    let shell = || Shell::new(&g, &spec, preset, PrintSize::default()).unwrap();
    let paint = shell().paint;
    // GLB: the page's colour of every outer vertex as COLOR_0, no texture.
    let glb = Export::new(MeshFormat::Glb, shell())
        .and_then(Export::run)
        .unwrap();
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let doc: Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    let primitive = &doc["meshes"][0]["primitives"][0];
    assert!(primitive["attributes"]["COLOR_0"].is_u64(), "{primitive}");
    assert!(primitive["attributes"]["TEXCOORD_0"].is_null());
    assert!(doc["images"].is_null());
    // PLY: the page's colours, vertex by vertex (the one colouring): the spines' dark tips,
    // darker than any colour of the pattern, reach the file.
    let ply = Export::new(MeshFormat::Ply, shell())
        .and_then(Export::run)
        .unwrap();
    let header_end = ply.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
    let header = std::str::from_utf8(&ply[..header_end]).unwrap();
    let count: usize = header
        .lines()
        .find_map(|l| l.strip_prefix("element vertex "))
        .unwrap()
        .parse()
        .unwrap();
    let ply_colours: Vec<[u8; 3]> = (0..count)
        .map(|i| {
            let at = header_end + 27 * i + 24;
            [ply[at], ply[at + 1], ply[at + 2]]
        })
        .collect();
    let lum = |c: [u8; 3]| luminance(paint.linear(c).map(f64::from));
    let pigment = lum(spec.colours.pigment.0);
    let darker = ply_colours
        .iter()
        .filter(|&&c| lum(c) < 0.8 * pigment)
        .count();
    assert!(darker > 20, "{darker} vertices darker than the pigment");
    let tips = outer
        .iter()
        .filter(|v| lum(paint.colour(v)) < 0.8 * pigment)
        .count();
    assert!(
        tips > 20
            && outer
                .iter()
                .all(|v| v.tint[3] < 1.0 || lum(paint.colour(v)) >= 0.99 * pigment)
    );
}

#[test]
fn links_carry_the_textures_and_bad_values_are_named() {
    let preset = presets::preset("murex-cabritii").unwrap();
    let mut spec = preset.spec.clone();
    let t = &mut implicit(&mut spec).textures;
    t.body.look = TextureKind::Ramp;
    t.spines.look = TextureKind::Pattern;
    t.canal_spines.tip = "102030".parse().unwrap();
    t.bumps.shade = 2.5;
    let link = encode(preset, &spec);
    for part in [
        "form.textures.body.look=ramp",
        "form.textures.spines.look=pattern",
        "form.textures.canal_spines.tip=102030",
        "form.textures.bumps.shade=2.5",
    ] {
        assert!(link.contains(part), "{link}");
    }
    let decoded = decode(&link);
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    assert_eq!(decoded.spec, spec);

    for (key, value) in [
        ("form.textures.spines.shade", "99"),
        ("form.textures.spines.shade", "nan"),
        ("form.textures.canal_spines.tip", "zzz"),
        ("form.textures.bumps.look", "plaid"),
    ] {
        let decoded = decode(&format!("v=1&preset=murex-cabritii&{key}={value}"));
        assert!(
            decoded.problems.iter().any(|p| p.key == key),
            "{key}={value}: {:?}",
            decoded.problems
        );
        assert!(
            check(implicit(&mut decoded.spec.clone())).is_ok(),
            "{key}={value}: the shell is built from what could be read"
        );
    }
    // A spec file (not a link) with a bad exponent is refused by the model, naming the key,
    // and repaired from the preset.
    let mut spoiled = preset.spec.clone();
    implicit(&mut spoiled).textures.spines.shade = f64::NAN;
    assert_refused_and_repaired(spoiled, &preset.spec, "form.textures.spines.shade");
}

#[test]
fn the_same_textures_give_the_same_bits_and_other_textures_only_other_colours() {
    let mut spec = spec_of("murex-cabritii");
    implicit(&mut spec).resolution = 48;
    let a = grown(&spec);
    assert_eq!(a.mesh_hash(), grown(&spec).mesh_hash());
    let mut other = spec.clone();
    implicit(&mut other).textures.spines.tip = "000000".parse().unwrap();
    let b = grown(&other);
    assert_ne!(a.mesh_hash(), b.mesh_hash());
    let (ma, mb) = (a.snapshot(), b.snapshot());
    assert_eq!(ma.indices, mb.indices);
    assert!(
        ma.vertices
            .iter()
            .zip(&mb.vertices)
            .all(|(x, y)| x.position == y.position && x.normal == y.normal),
        "the geometry does not depend on the colours"
    );
}

/// The texture of a part made `look` with image `image`.
fn imaged(image: ImageOf) -> PartTexture {
    PartTexture {
        look: TextureKind::Image,
        image,
        ..PartTexture::default()
    }
}

/// The image a part textured with `image` shows.
fn image_of(image: ImageOf) -> &'static ImageMap {
    match look(&imaged(image), MapOn::Part { start: 0.0 }) {
        Look::Image { map, .. } => map,
        other => panic!("{other:?}"),
    }
}

#[test]
fn every_species_offered_as_an_image_is_a_pattern_that_shows_one() {
    for &id in ImageOf::IDS {
        let image: ImageOf = serde_json::from_value(Value::String(id.into())).expect(id);
        assert_eq!(image.id(), id);
        let preset = presets::preset(id).expect(id);
        assert_ne!(preset.spec.pattern.model, Model::None, "{id}");
        // An image, not a flat colour: its texels' luminance spreads over a tenth at least.
        let map = image_of(image);
        let lums: Vec<f64> = (0..64)
            .flat_map(|i| (0..64).map(move |j| (f64::from(i) / 64.0, f64::from(j) / 64.0)))
            .map(|(u, v)| luminance(map.at(u, v)))
            .collect();
        let (low, high) = lums
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), &x| (l.min(x), h.max(x)));
        assert!(high - low > 0.1, "{id}: luminance {low}..{high}");
    }
}

#[test]
fn an_image_lies_around_and_along_a_spine_and_a_bump_and_on_the_bodys_growth() {
    let map = image_of(ImageOf::OlivaPorphyria);
    let close = |got: [f64; 4], want: [f64; 3], what: &str| {
        for (g, w) in got.into_iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{what}: {got:?} against {want:?}");
        }
        assert_eq!(got[3], 0.0, "{what}: no pattern shows");
    };
    // A spine along y from 0 to 3, its image starting a tenth of the way along.
    let spine = Primitive::Cone {
        from: DVec3::ZERO,
        to: DVec3::new(0.0, 3.0, 0.0),
        radii: [support_of(0.5), support_of(0.2)],
    };
    let start = 0.1;
    let tree = Node::leaf(
        spine.clone(),
        Texture::around(0.0).looking(Look::Image {
            map,
            on: MapOn::Part { start },
        }),
    );
    // Along: a point 2.1 up is (0.7 − 0.1)/0.9 of the way from the image's first row to its
    // last; one at the base, before the start, shows the first row.
    let across = |p: DVec3| spine.mapped(p)[0];
    let p = DVec3::new(0.3, 2.1, 0.0);
    close(
        tree.probe(p).paint.tint(),
        map.at(across(p), 0.6 / 0.9),
        "2.1 up",
    );
    let p = DVec3::new(0.3, 0.15, 0.0);
    close(
        tree.probe(p).paint.tint(),
        map.at(across(p), 0.0),
        "at the base",
    );
    // Around: a quarter turn about the spine is a quarter of the image across, whichever way
    // the spine points.
    for k in 0..8 {
        let a = f64::from(k) * std::f64::consts::TAU / 8.0;
        let at = |a: f64| DVec3::new(0.2 * a.cos(), 1.0, 0.2 * a.sin());
        let step = (across(at(a + std::f64::consts::FRAC_PI_2)) - across(at(a))).rem_euclid(1.0);
        assert!(
            (step - 0.25).abs() < 1e-9 || (step - 0.75).abs() < 1e-9,
            "a quarter turn from {a}: {step}"
        );
    }
    // A bump standing out along x: its top is the image's last row, where it leaves the
    // surface (a right angle from x) its first; around x, a quarter turn from y to z is a
    // quarter of the image across.
    let bump = Primitive::Point {
        centre: DVec3::ZERO,
        radius: support_of(1.0),
    };
    let tree = Node::leaf(
        bump,
        Texture::around(0.0).looking(Look::Image {
            map,
            on: MapOn::Part { start: 0.0 },
        }),
    );
    let r = 0.7;
    close(
        tree.probe(DVec3::X * r).paint.tint(),
        map.at(0.0, 1.0),
        "its top",
    );
    close(
        tree.probe(DVec3::Y * r).paint.tint(),
        map.at(0.0, 0.0),
        "its rim, y",
    );
    close(
        tree.probe(DVec3::Z * r).paint.tint(),
        map.at(0.25, 0.0),
        "its rim, z",
    );
    let halfway = DVec3::new(1.0, 0.0, 1.0).normalize() * r;
    close(
        tree.probe(halfway).paint.tint(),
        map.at(0.25, 0.5),
        "half way up, z",
    );
    // On the body, the image runs on the growth: across it along the generating curve, along
    // it the growth time over the rows.
    let body = Primitive::Point {
        centre: DVec3::ZERO,
        radius: support_of(1.0),
    };
    let rows = 200.0;
    let at = Node::leaf(
        body,
        Texture::around(50.0).looking(Look::Image {
            map,
            on: MapOn::Growth { rows },
        }),
    );
    let p = DVec3::new(0.0, 0.3, 0.1);
    let [r, g, b, _] = at.probe(p).paint.tint();
    let want = map.at(0.25, 50.0 / rows);
    for (got, want) in [r, g, b].into_iter().zip(want) {
        assert!((got - want).abs() < 1e-12, "{got} {want}");
    }
}

#[test]
fn a_murex_wears_another_species_pattern_on_its_spines_from_a_link() {
    let link = "v=1&preset=murex-cabritii&form.resolution=64\
                &form.textures.spines.look=image&form.textures.spines.image=oliva-porphyria\
                &form.textures.bumps.look=image&form.textures.bumps.image=ca-waves";
    let decoded = decode(link);
    assert!(decoded.problems.is_empty(), "{:?}", decoded.problems);
    let spec = decoded.spec;
    let mut read = spec.clone();
    let spines = implicit(&mut read).textures.spines;
    assert_eq!(
        (spines.look, spines.image),
        (TextureKind::Image, ImageOf::OlivaPorphyria)
    );
    let preset = presets::preset("murex-cabritii").unwrap();
    let again = encode(preset, &spec);
    assert!(
        again.contains("form.textures.spines.image=oliva-porphyria"),
        "{again}"
    );
    assert_eq!(decode(&again).spec, spec);
    let bad = decode("v=1&preset=murex-cabritii&form.textures.spines.image=nautilus");
    assert!(
        (bad.problems.iter()).any(|p| p.key == "form.textures.spines.image"),
        "{:?}",
        bad.problems
    );

    // Grown: the same link gives the same bits; the geometry is the ramp's, and the spines
    // show more colours than a ramp along them gives.
    let a = grown(&spec);
    assert_eq!(a.mesh_hash(), grown(&spec).mesh_hash());
    let mut ramped = spec.clone();
    *implicit(&mut ramped).textures = TexturesSpec::default();
    let b = grown(&ramped);
    let (ma, mb) = (a.snapshot(), b.snapshot());
    assert_eq!(ma.indices, mb.indices);
    assert!(
        (ma.vertices.iter().zip(&mb.vertices)).all(|(x, y)| x.position == y.position),
        "the geometry does not depend on the textures"
    );
    // Where no pattern shows, a ramp's colour lies on the line from its base to its tip; most
    // of the imaged parts' colours lie off every ramp's line.
    let textures = TexturesSpec::default();
    let lines = [textures.spines, textures.bumps].map(|t| {
        (
            t.base.linear().map(f64::from),
            t.tip.linear().map(f64::from),
        )
    });
    let off_ramps = |vertices: &[Vertex]| {
        let parts: Vec<[f64; 3]> = (vertices.iter())
            .filter(|v| v.is_outer() && v.tint[3] == 0.0)
            .map(|v| std::array::from_fn(|k| f64::from(v.tint[k])))
            .collect();
        let off = (parts.iter())
            .filter(|&&c| lines.iter().all(|&(a, b)| off_segment(c, a, b) > 0.02))
            .count();
        off as f64 / parts.len().max(1) as f64
    };
    let (imaged, ramps) = (off_ramps(&ma.vertices), off_ramps(&mb.vertices));
    assert!(
        imaged > 0.3 && ramps < 0.05,
        "off the ramps: {imaged:.3} of the imaged parts' colours, {ramps:.3} of the ramps'"
    );
}

/// How far the colour `c` lies from the segment from `a` to `b`.
fn off_segment(c: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    let (c, a, b) = (DVec3::from(c), DVec3::from(a), DVec3::from(b));
    let t = ((c - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
    (c - (a + (b - a) * t)).length()
}
