// An emboss kernel: the difference across the diagonal, lifted to mid grey, as if the
// picture were lit from the upper left. `strength` (a <filter> attribute) scales the relief.
// The renderer provides pixel(at) (the input at column, row `at`, clamped to its edges) and
// calls filter_pixel for every output pixel.
uniform float strength;

vec4 filter_pixel(ivec2 at) {
    vec3 relief = pixel(at + ivec2(-1, 1)).rgb - pixel(at + ivec2(1, -1)).rgb;
    float grey = dot(relief, vec3(0.299, 0.587, 0.114));
    return vec4(vec3(0.5 + strength * grey), 1.0);
}
