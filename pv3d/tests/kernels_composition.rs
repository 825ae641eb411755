//! configs/kernels.pv3d.xml (the paper's Fig. 6f) runs offscreen without an error and shows
//! its filtered tiles: the GLSL emboss tile's flat mid grey, the Sobel tile's black.

mod support;

#[test]
fn the_kernels_composition_shows_its_filtered_tiles() {
    let png = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("kernels.png");
    let image = support::screenshot(&["configs/kernels.pv3d.xml"], "1.0", "1280x800", &png);
    let grey = |lo: u8, hi: u8| {
        support::count(&image, |p| {
            (lo..=hi).contains(&p[0]) && p[0] == p[1] && p[1] == p[2]
        })
    };
    let emboss_flat = grey(124, 132);
    let black = grey(0, 4);
    assert!(
        emboss_flat > 10_000,
        "emboss mid grey: {emboss_flat} ({})",
        png.display()
    );
    assert!(black > 10_000, "edges and Laplacian black: {black}");
}
