//! The GLSL of the kernel passes. Every pass is one fragment shader over a full-screen
//! triangle, drawn at the picture's own size: `filter_pixel(at)` gives the output for the
//! pixel at column, row `at`; `pixel(at)` reads the input, clamped to its edges.
//! The CPU reference in [`super::reference`] computes the same sums.

/// The vertex shader of every pass: one triangle covering the target, no vertex buffer.
pub const PASS_VERTEX: &str = r#"
out vec2 v_uv;
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    v_uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
"#;

/// What a kernel's source may use, before it.
pub const PASS_PRELUDE: &str = r#"
uniform sampler2D u_image;
in vec2 v_uv;
out vec4 f_color;
vec4 pixel(ivec2 at) {
    ivec2 last = textureSize(u_image, 0) - ivec2(1);
    return texelFetch(u_image, clamp(at, ivec2(0), last), 0);
}
"#;

/// Calls the kernel, after it.
pub const PASS_MAIN: &str = r#"
void main() { f_color = filter_pixel(ivec2(gl_FragCoord.xy)); }
"#;

/// One direction of a box blur: the mean of `2r + 1` pixels along `u_step`.
pub const BOX_BLUR: &str = r#"
uniform ivec2 u_step;
uniform int u_radius;
vec4 filter_pixel(ivec2 at) {
    vec4 sum = vec4(0.0);
    for (int i = -u_radius; i <= u_radius; i++) {
        sum += pixel(at + u_step * i);
    }
    return sum / float(2 * u_radius + 1);
}
"#;

/// One direction of an erosion (minimum) or a dilation (maximum) along `u_step`.
pub const MIN_MAX: &str = r#"
uniform ivec2 u_step;
uniform int u_radius;
uniform int u_take_max;
vec4 filter_pixel(ivec2 at) {
    vec4 kept = pixel(at);
    for (int i = -u_radius; i <= u_radius; i++) {
        vec4 p = pixel(at + u_step * i);
        kept = u_take_max != 0 ? max(kept, p) : min(kept, p);
    }
    return kept;
}
"#;

/// The four neighbours of a pixel summed, for sharpen and Laplacian.
const RING: &str = r#"
vec4 ring(ivec2 at) {
    return pixel(at + ivec2(1, 0)) + pixel(at - ivec2(1, 0))
         + pixel(at + ivec2(0, 1)) + pixel(at - ivec2(0, 1));
}
"#;

pub fn sharpen() -> String {
    format!(
        "{RING}{}",
        r#"
uniform float u_amount;
vec4 filter_pixel(ivec2 at) {
    vec4 c = pixel(at);
    return vec4(clamp(c.rgb + u_amount * (4.0 * c.rgb - ring(at).rgb), 0.0, 1.0), c.a);
}
"#
    )
}

pub fn laplacian() -> String {
    format!(
        "{RING}{}",
        r#"
vec4 filter_pixel(ivec2 at) {
    vec4 c = pixel(at);
    return vec4(clamp(abs(4.0 * c.rgb - ring(at).rgb), 0.0, 1.0), c.a);
}
"#
    )
}

/// Sobel on the luminance (Rec. 601 weights), the magnitude as grey.
pub const SOBEL: &str = r#"
float luma(ivec2 at) { return dot(pixel(at).rgb, vec3(0.299, 0.587, 0.114)); }
vec4 filter_pixel(ivec2 at) {
    float gx = luma(at + ivec2(1, -1)) + 2.0 * luma(at + ivec2(1, 0)) + luma(at + ivec2(1, 1))
             - luma(at + ivec2(-1, -1)) - 2.0 * luma(at + ivec2(-1, 0)) - luma(at + ivec2(-1, 1));
    float gy = luma(at + ivec2(-1, 1)) + 2.0 * luma(at + ivec2(0, 1)) + luma(at + ivec2(1, 1))
             - luma(at + ivec2(-1, -1)) - 2.0 * luma(at + ivec2(0, -1)) - luma(at + ivec2(1, -1));
    float m = clamp(length(vec2(gx, gy)), 0.0, 1.0);
    return vec4(vec3(m), pixel(at).a);
}
"#;

/// The fragment shader of a pass running `kernel`, after `header`. `#line 1` makes the
/// driver's error lines count from the kernel's own first line, so that an error in a file
/// names the file's line.
pub fn fragment(header: &str, kernel: &str) -> String {
    format!("{header}{PASS_PRELUDE}#line 1\n{kernel}\n{PASS_MAIN}")
}
