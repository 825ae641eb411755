//! Colour names Stage world files use (X11's names, case and spaces ignored), as RGB: the
//! common ones and the `gray0`…`gray100` ramp that Stage's own includes use.

/// X11's `grayN` levels, N = 0 to 100 (not quite N × 2.55 rounded: X11's own table).
const GRAY_RAMP: [u8; 101] = [
    0, 3, 5, 8, 10, 13, 15, 18, 20, 23, 26, 28, 31, 33, 36, 38, 41, 43, 46, 48, 51, 54, 56, 59, 61,
    64, 66, 69, 71, 74, 77, 79, 82, 84, 87, 89, 92, 94, 97, 99, 102, 105, 107, 110, 112, 115, 117,
    120, 122, 125, 127, 130, 133, 135, 138, 140, 143, 145, 148, 150, 153, 156, 158, 161, 163, 166,
    168, 171, 173, 176, 179, 181, 184, 186, 189, 191, 194, 196, 199, 201, 204, 207, 209, 212, 214,
    217, 219, 222, 224, 227, 229, 232, 235, 237, 240, 242, 245, 247, 250, 252, 255,
];

pub fn by_name(name: &str) -> Option<[u8; 3]> {
    let name = name.to_ascii_lowercase().replace(' ', "");
    if let Some(level) = name
        .strip_prefix("gray")
        .or_else(|| name.strip_prefix("grey"))
        .filter(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|n| n.parse::<usize>().ok())
    {
        let v = *GRAY_RAMP.get(level)?;
        return Some([v, v, v]);
    }
    Some(match name.as_str() {
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
        "darkgray" | "darkgrey" => [127, 127, 127],
        "lightgray" | "lightgrey" => [211, 211, 211],
        "dimgray" | "dimgrey" => [105, 105, 105],
        "slategray" | "slategrey" => [112, 128, 144],
        "darkslategray" | "darkslategrey" => [47, 79, 79],
        "brown" => [165, 42, 42],
        "pink" => [255, 192, 203],
        "darkgreen" => [0, 100, 0],
        "darkblue" | "navy" => [0, 0, 139],
        "navyblue" => [0, 0, 128],
        "royalblue" => [65, 105, 225],
        "dodgerblue" => [30, 144, 255],
        "skyblue" => [135, 206, 235],
        "steelblue" => [70, 130, 180],
        "lightblue" => [173, 216, 230],
        "turquoise" => [64, 224, 208],
        "darkcyan" => [0, 139, 139],
        "seagreen" => [46, 139, 87],
        "limegreen" => [50, 205, 50],
        "forestgreen" => [34, 139, 34],
        "lightgreen" => [144, 238, 144],
        "khaki" => [240, 230, 140],
        "lightyellow" => [255, 255, 224],
        "gold" => [255, 215, 0],
        "sienna" => [160, 82, 45],
        "beige" => [245, 245, 220],
        "wheat" => [245, 222, 179],
        "tan" => [210, 180, 140],
        "chocolate" => [210, 105, 30],
        "firebrick" => [178, 34, 34],
        "salmon" => [250, 128, 114],
        "darkorange" => [255, 140, 0],
        "coral" => [255, 127, 80],
        "tomato" => [255, 99, 71],
        "maroon" => [176, 48, 96],
        "violet" => [238, 130, 238],
        "plum" => [221, 160, 221],
        "orchid" => [218, 112, 214],
        "darkmagenta" => [139, 0, 139],
        "darkred" => [139, 0, 0],
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::by_name;

    #[test]
    fn names_as_x11_writes_them() {
        assert_eq!(by_name("gray90"), Some([229, 229, 229]));
        assert_eq!(by_name("Grey30"), Some([77, 77, 77]));
        assert_eq!(by_name("NavyBlue"), by_name("navy blue"));
        assert_eq!(by_name("gray101"), None);
        assert_eq!(by_name("gray"), Some([190, 190, 190]));
        assert_eq!(by_name("chartreuse9"), None);
    }
}
