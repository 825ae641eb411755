//! Where each blob goes on the window's canvas: the blobfinder reports pixel boxes in its own
//! image's size, the canvas shows that image scaled, so the boxes are scaled the same way.
//! Pure, so that the mapping is tested without a window.

use egui::{Color32, Pos2, Rect, pos2};
use player_proto::interfaces::blobfinder::{Blob, BlobfinderData};

/// One blob as drawn: its box on the canvas, its colour and its caption.
#[derive(Debug, Clone, PartialEq)]
pub struct BlobBox {
    pub rect: Rect,
    pub color: Color32,
    pub caption: String,
    pub centroid: Pos2,
}

/// A blob's colour as Player packs it: `0x00RRGGBB`.
pub fn blob_color(packed: u32) -> Color32 {
    let [_, r, g, b] = packed.to_be_bytes();
    Color32::from_rgb(r, g, b)
}

/// The blobs of `data` on a canvas filling `canvas`. An image of unknown size (0) maps
/// nothing: its pixel boxes cannot be placed.
pub fn blob_boxes(data: &BlobfinderData, canvas: Rect) -> Vec<BlobBox> {
    if data.width == 0 || data.height == 0 {
        return Vec::new();
    }
    let sx = canvas.width() / data.width as f32;
    let sy = canvas.height() / data.height as f32;
    let place = |x: u32, y: u32| pos2(canvas.min.x + x as f32 * sx, canvas.min.y + y as f32 * sy);
    data.blobs
        .iter()
        .map(|blob: &Blob| BlobBox {
            // The right and bottom pixels are inside the box: it ends one pixel further.
            rect: Rect::from_min_max(
                place(blob.left, blob.top),
                place(blob.right + 1, blob.bottom + 1),
            )
            .intersect(canvas),
            color: blob_color(blob.color),
            caption: if blob.range > 0.0 {
                format!("{} · {:.1} m", blob.id, blob.range)
            } else {
                format!("{}", blob.id)
            },
            centroid: place(blob.x, blob.y),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn blob(left: u32, top: u32, right: u32, bottom: u32) -> Blob {
        Blob {
            id: 3,
            color: 0x00ff_0000,
            left,
            top,
            right,
            bottom,
            x: (left + right) / 2,
            y: (top + bottom) / 2,
            range: 1.25,
            ..Blob::default()
        }
    }

    #[test]
    fn boxes_scale_with_the_canvas() {
        let data = BlobfinderData {
            width: 80,
            height: 60,
            blobs: vec![blob(10, 20, 19, 29)],
        };
        let canvas = Rect::from_min_size(pos2(100.0, 50.0), egui::vec2(320.0, 240.0));
        let boxes = blob_boxes(&data, canvas);
        assert_eq!(
            boxes[0].rect,
            Rect::from_min_max(pos2(140.0, 130.0), pos2(180.0, 170.0))
        );
        assert_eq!(boxes[0].color, Color32::from_rgb(255, 0, 0));
        assert_eq!(boxes[0].caption, "3 · 1.2 m");
    }

    #[test]
    fn boxes_stay_on_the_canvas_and_an_unsized_image_places_none() {
        let canvas = Rect::from_min_size(Pos2::ZERO, egui::vec2(80.0, 60.0));
        let data = BlobfinderData {
            width: 80,
            height: 60,
            blobs: vec![blob(70, 50, 200, 200)],
        };
        assert_eq!(blob_boxes(&data, canvas)[0].rect.max, pos2(80.0, 60.0));
        let no_size = BlobfinderData { width: 0, ..data };
        assert!(blob_boxes(&no_size, canvas).is_empty());
        assert_eq!(blob_color(0x0012_3456), Color32::from_rgb(0x12, 0x34, 0x56));
    }
}
