// The shell: outer surface painted with the pigmentation pattern, inner surface and edges in
// the interior colour, lit by a key, a fill and a rim light, both sides of the surface shaded.
// The material (Fowler et al. 1992, §5, "improved rendering") adds polished reflections of a
// studio environment with Fresnel, highlights stretched along the growth lines (the tangent
// of the pattern's x, taken from screen-space derivatives), light through the wall where it is
// lit from behind, and darkening with depth into the opening. The ground quad under the shell
// is drawn in the background colour, darkened by a soft contact shadow.
//
// Or the shell is drawn in lines on paper, as Kawaguchi drew GROWTH's shells on a vector
// display: lines on the iso-lines of the pattern coordinates that the form puts on its facets'
// edges (or on a sparse set of rims and lines of growth), every one of them about a pixel wide,
// and its outline; the depth test removes the hidden ones.
//
// A pane is drawn in perspective (eye.w = 1: the eye is a point) or orthographically (eye.w =
// 0: eye.xyz is the direction towards the viewer, the same for every point).

struct Globals {
    view_proj: mat4x4<f32>,
    // Shell space to display space (a rotation, so it also turns normals).
    model: mat4x4<f32>,
    eye: vec4<f32>,
    ground: vec4<f32>,
    interior: vec4<f32>,
    // x: cells per row, y: rows grown, z: rows per texture block, w: 1 when a pattern exists.
    pattern: vec4<f32>,
    // x: 1 when the target is not sRGB and the shader must encode, y: rows per whorl.
    options: vec4<f32>,
    // Gloss, anisotropy, translucency, occlusion, each 0 to 1.
    material: vec4<f32>,
    // x: strength of the ground shadow.
    shadow: vec4<f32>,
    // The clear colour, linear.
    background: vec4<f32>,
    // x: 1 for a line drawing, y: lines across the edge (at x = k / y), z: rows between rims.
    lines: vec4<f32>,
    // The pane's width and height in pixels.
    pixels: vec4<f32>,
}

@group(0) @binding(0) var<uniform> g: Globals;
@group(0) @binding(1) var pattern_texture: texture_2d<f32>;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) pattern: vec2<f32>,
    @location(3) surface: f32,
    // Colours blended by field on an implicit shell's parts: rgb already weighted, a the
    // pattern's share (Galbraith et al. §3.4).
    @location(4) tint: vec4<f32>,
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) pattern: vec2<f32>,
    @location(3) @interpolate(flat) surface: f32,
    @location(4) tint: vec4<f32>,
}

// A vertex in display and clip space.
fn place(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    let world = g.model * vec4<f32>(v.position, 1.0);
    out.clip = g.view_proj * world;
    out.world = world.xyz;
    out.normal = (g.model * vec4<f32>(v.normal, 0.0)).xyz;
    out.pattern = v.pattern;
    out.surface = v.surface;
    out.tint = v.tint;
    return out;
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    return place(v);
}

// The line drawing's outline, drawn before the shell: the faces turned away from the eye (which
// lie behind those turned towards it), pushed out along their normals by a pixel and a half on
// screen and a little back in depth, in ink. The shell drawn over them covers all of it but a
// band around its silhouette and along every occluding contour.
@vertex
fn vs_outline(v: VertexIn) -> VertexOut {
    var out = place(v);
    let normal = (g.view_proj * vec4<f32>(out.normal, 0.0)).xy * g.pixels.xy;
    let length = max(sqrt(dot(normal, normal)), 1e-6);
    out.clip = vec4<f32>(
        out.clip.xy + normal / length * 3.0 / g.pixels.xy * out.clip.w,
        out.clip.z + 0.002 * out.clip.w,
        out.clip.w,
    );
    return out;
}

@fragment
fn fs_outline() -> @location(0) vec4<f32> {
    return vec4<f32>(0.02, 0.02, 0.03, 1.0);
}

// One texel of the pattern; rows are folded into blocks of `pattern.z` rows laid side by side.
fn texel(cell: i32, row: i32) -> vec3<f32> {
    let cells = i32(g.pattern.x);
    let block_rows = i32(g.pattern.z);
    let c = clamp(cell, 0, cells - 1);
    let r = clamp(row, 0, max(i32(g.pattern.y) - 1, 0));
    let block = r / block_rows;
    return textureLoad(pattern_texture, vec2<i32>(block * cells + c, r - block * block_rows), 0).rgb;
}

// Bilinear sample at (position along the edge in [0, 1], row): x = 0 and 1 fall on the
// centres of the end cells, a whole row number on the centre of that row.
fn pigment(at: vec2<f32>) -> vec3<f32> {
    let x = at.x * (g.pattern.x - 1.0);
    let y = at.y;
    let x0 = floor(x);
    let y0 = floor(y);
    let fx = x - x0;
    let fy = y - y0;
    let c = i32(x0);
    let r = i32(y0);
    let top = mix(texel(c, r), texel(c + 1, r), fx);
    let bottom = mix(texel(c, r + 1), texel(c + 1, r + 1), fx);
    return mix(top, bottom, fy);
}

// Isotropic (Blinn-Phong) and anisotropic (Ward-like, stretched along `t`) highlights, mixed
// by the material's anisotropy; diffuse light, and the light passing through the wall from
// behind (a wrapped back-light tinted by the shell's colour).
fn light(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, t: vec3<f32>, colour: vec3<f32>, albedo: vec3<f32>, shine: f32) -> vec3<f32> {
    let nl = dot(n, l);
    let diffuse = max(nl, 0.0);
    let h = normalize(l + v);
    let lit = select(0.0, 1.0, diffuse > 0.0);
    let iso = pow(max(dot(n, h), 0.0), shine);
    let hn = max(dot(h, n), 1e-3);
    let ht = dot(h, t) / 0.8;
    let hb = dot(h, cross(n, t)) / 0.09;
    let aniso = exp(-(ht * ht + hb * hb) / (hn * hn)) * 1.2;
    let a = g.material.y * select(0.0, 1.0, dot(t, t) > 0.5);
    let specular = mix(iso, aniso, a) * lit * (0.35 + 0.9 * g.material.x);
    let behind = max(-nl, 0.0);
    let through = g.material.z * (0.25 * behind + 0.6 * pow(max(dot(v, -l), 0.0), 4.0)) * behind;
    let warm = albedo * vec3<f32>(1.0, 0.82, 0.66);
    return colour * (albedo * diffuse + vec3<f32>(specular) + warm * through);
}

// A studio around the shell: a warm floor, a cool sky, and two soft boxes (key and strip).
fn environment(r: vec3<f32>) -> vec3<f32> {
    let sky = mix(vec3<f32>(0.16, 0.14, 0.12), vec3<f32>(0.52, 0.56, 0.62), smoothstep(-0.25, 0.65, r.y));
    let key = pow(max(dot(r, normalize(vec3<f32>(-0.45, 0.75, 0.55))), 0.0), 48.0) * 2.6;
    let strip = pow(max(dot(r, normalize(vec3<f32>(0.75, 0.25, 0.35))), 0.0), 20.0) * 0.9;
    return sky + vec3<f32>(key + strip);
}

// How much of a pixel the line drawing's lines cover: `cells` is the position in units of the
// spacing between lines (lines on whole numbers), `width` its change across one pixel. Every
// line is drawn, about a pixel wide at any zoom, as a vector display's beam draws every edge:
// where lines crowd closer than a couple of pixels they are no longer told apart, and the pixel
// takes the share of it their ink covers (a pixel's width of line per spacing), so crowded
// lines merge into dark ink instead of fading away or flickering in moiré.
fn ink(cells: vec2<f32>, width: vec2<f32>) -> f32 {
    let w = max(width, vec2<f32>(1e-6));
    let pixels = abs(fract(cells + 0.5) - 0.5) / w;
    let sharp = vec2<f32>(1.0) - smoothstep(vec2<f32>(0.3), vec2<f32>(0.9), pixels);
    let crowded = min(w * 1.2, vec2<f32>(1.0));
    let line = mix(sharp, crowded, smoothstep(vec2<f32>(0.3), vec2<f32>(0.6), w));
    return max(line.x, line.y);
}

fn encode_srgb(c: vec3<f32>) -> vec3<f32> {
    let low = c * 12.92;
    let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(high, low, c <= vec3<f32>(0.0031308));
}

@fragment
fn fs_main(in: VertexOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    // Derivatives first, in uniform control flow: the tangent along the growth lines is where
    // the pattern's x (the position along the growing edge) increases.
    let dpx = dpdx(in.world);
    let dpy = dpdy(in.world);
    let dux = dpdx(in.pattern);
    let duy = dpdy(in.pattern);
    let along = dpx * duy.y - dpy * dux.y;
    let cells = vec2<f32>(in.pattern.x * g.lines.y, in.pattern.y / max(g.lines.z, 1e-6));
    let cells_width = fwidth(cells);
    let toward = select(g.eye.xyz, g.eye.xyz - in.world, g.eye.w > 0.5);
    if (in.surface > 2.5) {
        // The ground: a soft shadow under the shell, seen only from above.
        if (!front) {
            discard;
        }
        let d = dot(in.pattern, in.pattern);
        let shade = g.shadow.x * 0.55 * exp(-2.6 * d) * smoothstep(1.0, 0.6, d);
        var ground = g.background.rgb * (1.0 - shade);
        if (g.options.x > 0.5) {
            ground = encode_srgb(clamp(ground, vec3<f32>(0.0), vec3<f32>(1.0)));
        }
        return vec4<f32>(ground, 1.0);
    }
    if (g.lines.x > 0.5) {
        // Paper and ink (the outline is drawn behind, see vs_outline). Only the outer surface
        // and the inside of the wall carry the grid: the pattern coordinates of the caps and
        // lip fan out from their centres and draw no edges.
        let coverage = select(0.0, ink(cells, cells_width), in.surface < 1.5);
        var drawn = mix(vec3<f32>(0.98, 0.975, 0.96), vec3<f32>(0.02, 0.02, 0.03), coverage);
        if (g.options.x > 0.5) {
            drawn = encode_srgb(drawn);
        }
        return vec4<f32>(drawn, 1.0);
    }
    var n = normalize(in.normal);
    if (!front) {
        n = -n;
    }
    let v = normalize(toward);
    var t = along - n * dot(n, along);
    t = select(vec3<f32>(0.0), normalize(t), dot(t, t) > 1e-20);
    var albedo: vec3<f32>;
    var shine = 48.0;
    // How far into the opening, in whorls of growth (0 at the growing edge).
    let depth = max(g.pattern.y - in.pattern.y, 0.0) / max(g.options.y, 1.0);
    let hollow = mix(1.0, mix(0.12, 1.0, exp(-2.5 * depth)), g.material.w);
    if (in.surface < 0.5) {
        if (g.pattern.w > 0.5) {
            albedo = pigment(in.pattern);
        } else {
            albedo = g.ground.rgb;
        }
        albedo = in.tint.a * albedo + in.tint.rgb;
        // The side facing into the shell (seen through a single-surface opening) is paler,
        // and darkens with depth like the inside of a wall.
        if (!front) {
            albedo = mix(albedo, g.interior.rgb, 0.6) * hollow;
        }
    } else {
        albedo = g.interior.rgb;
        shine = 80.0;
        if (in.surface < 1.5) {
            albedo = albedo * hollow;
        }
    }
    let key = light(n, v, normalize(vec3<f32>(-0.45, 0.75, 0.55)), t, vec3<f32>(1.0, 0.97, 0.92), albedo, shine);
    let fill = light(n, v, normalize(vec3<f32>(0.7, 0.1, 0.45)), t, vec3<f32>(0.32, 0.36, 0.42), albedo, shine);
    let rim = light(n, v, normalize(vec3<f32>(0.1, 0.3, -0.9)), t, vec3<f32>(0.35, 0.33, 0.3), albedo, shine);
    let sky = mix(vec3<f32>(0.10, 0.09, 0.08), vec3<f32>(0.22, 0.24, 0.27), 0.5 + 0.5 * n.y);
    // Polish: the environment reflected, stronger at grazing angles (Schlick's Fresnel).
    let fresnel = 0.04 + 0.96 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
    let reflection = environment(reflect(-v, n)) * fresnel * g.material.x * mix(1.0, hollow, 0.8);
    // A soft shoulder (extended Reinhard, white point 1.6) keeps the relief of pale shells
    // in the highlights instead of clipping it.
    let lit = (key + fill + rim + sky * albedo) * 1.15 * (1.0 - 0.5 * fresnel * g.material.x) + reflection;
    var colour = lit * (vec3<f32>(1.0) + lit / 2.56) / (vec3<f32>(1.0) + lit);
    if (g.options.x > 0.5) {
        colour = encode_srgb(clamp(colour, vec3<f32>(0.0), vec3<f32>(1.0)));
    }
    return vec4<f32>(colour, 1.0);
}
