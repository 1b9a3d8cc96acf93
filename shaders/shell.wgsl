// The shell: outer surface painted with the pigmentation pattern, inner surface and edges in
// the interior colour, lit by a key, a fill and a rim light with Blinn-Phong highlights, both
// sides of the surface shaded.

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
}

@group(0) @binding(0) var<uniform> g: Globals;
@group(0) @binding(1) var pattern_texture: texture_2d<f32>;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) pattern: vec2<f32>,
    @location(3) surface: f32,
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) pattern: vec2<f32>,
    @location(3) @interpolate(flat) surface: f32,
}

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    let world = g.model * vec4<f32>(v.position, 1.0);
    out.clip = g.view_proj * world;
    out.world = world.xyz;
    out.normal = (g.model * vec4<f32>(v.normal, 0.0)).xyz;
    out.pattern = v.pattern;
    out.surface = v.surface;
    return out;
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

fn light(n: vec3<f32>, v: vec3<f32>, l: vec3<f32>, colour: vec3<f32>, albedo: vec3<f32>, shine: f32) -> vec3<f32> {
    let diffuse = max(dot(n, l), 0.0);
    let h = normalize(l + v);
    let specular = pow(max(dot(n, h), 0.0), shine) * select(0.0, 1.0, diffuse > 0.0);
    return colour * (albedo * diffuse + vec3<f32>(0.35) * specular);
}

fn encode_srgb(c: vec3<f32>) -> vec3<f32> {
    let low = c * 12.92;
    let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(high, low, c <= vec3<f32>(0.0031308));
}

@fragment
fn fs_main(in: VertexOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    var n = normalize(in.normal);
    if (!front) {
        n = -n;
    }
    let v = normalize(g.eye.xyz - in.world);
    var albedo: vec3<f32>;
    var shine = 48.0;
    if (in.surface < 0.5) {
        if (g.pattern.w > 0.5) {
            albedo = pigment(in.pattern);
        } else {
            albedo = g.ground.rgb;
        }
        // The side facing into the shell (seen through a single-surface opening) is paler.
        if (!front) {
            albedo = mix(albedo, g.interior.rgb, 0.6);
        }
    } else {
        albedo = g.interior.rgb;
        shine = 80.0;
        if (in.surface < 1.5) {
            // The inside darkens with depth into the opening, measured in whorls of growth.
            let depth = max(g.pattern.y - in.pattern.y, 0.0) / max(g.options.y, 1.0);
            albedo = albedo * mix(0.25, 1.0, exp(-2.5 * depth));
        }
    }
    let key = light(n, v, normalize(vec3<f32>(-0.45, 0.75, 0.55)), vec3<f32>(1.0, 0.97, 0.92), albedo, shine);
    let fill = light(n, v, normalize(vec3<f32>(0.7, 0.1, 0.45)), vec3<f32>(0.32, 0.36, 0.42), albedo, shine);
    let rim = light(n, v, normalize(vec3<f32>(0.1, 0.3, -0.9)), vec3<f32>(0.35, 0.33, 0.3), albedo, shine);
    let sky = mix(vec3<f32>(0.10, 0.09, 0.08), vec3<f32>(0.22, 0.24, 0.27), 0.5 + 0.5 * n.y);
    // A soft shoulder (extended Reinhard, white point 1.6) keeps the relief of pale shells
    // in the highlights instead of clipping it.
    let lit = (key + fill + rim + sky * albedo) * 1.15;
    var colour = lit * (vec3<f32>(1.0) + lit / 2.56) / (vec3<f32>(1.0) + lit);
    if (g.options.x > 0.5) {
        colour = encode_srgb(clamp(colour, vec3<f32>(0.0), vec3<f32>(1.0)));
    }
    return vec4<f32>(colour, 1.0);
}
