//! Colour names Stage world files use (a few of X11's), as RGB.

pub fn by_name(name: &str) -> Option<[u8; 3]> {
    Some(match name.to_ascii_lowercase().replace(' ', "").as_str() {
        "red" => [255, 0, 0],
        "green" => [0, 200, 0],
        "blue" => [0, 0, 255],
        "yellow" => [255, 255, 0],
        "cyan" => [0, 255, 255],
        "magenta" => [255, 0, 255],
        "orange" => [255, 165, 0],
        "purple" => [160, 32, 240],
        "white" => [255, 255, 255],
        "black" => [0, 0, 0],
        "gray" | "grey" => [190, 190, 190],
        "darkgray" | "darkgrey" | "gray50" | "grey50" => [127, 127, 127],
        "lightgray" | "lightgrey" => [211, 211, 211],
        "brown" => [165, 42, 42],
        "pink" => [255, 192, 203],
        "darkgreen" => [0, 100, 0],
        "darkblue" | "navy" => [0, 0, 139],
        "gray30" | "grey30" => [77, 77, 77],
        _ => return None,
    })
}
