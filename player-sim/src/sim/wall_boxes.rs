//! The wall cells of a raster as few boxes: a hall's walls are a handful of rectangles (the
//! 1 024-robot swarm's border and six inner walls: ten boxes once a bitmap's rows of pixels are
//! merged), listed by bucket of 5 m, so that a question about the walls near a point (which
//! beams may meet one: `wall_box_beams.rs`; a tile's cells: `wall_tiles.rs`) reads the few
//! boxes there instead of millions of cells.

/// Side of the buckets the boxes are listed in, in cells (5 m at 2 cm).
const BUCKET: i64 = 256;

/// A wall's cells: columns `x0..=x1` and rows `y0..=y1` (global cells).
pub(super) type CellBox = [i64; 4];

/// The boxes holding every wall cell of a raster, listed by bucket.
#[derive(Debug, Clone, PartialEq, Default)]
pub(super) struct WallBoxes {
    boxes: Vec<CellBox>,
    /// Global cell of the first bucket's first column and row.
    first: (i64, i64),
    columns: i64,
    rows: i64,
    /// Bucket `k`'s boxes are `members[starts[k]..starts[k + 1]]`.
    starts: Vec<u32>,
    members: Vec<u32>,
}

/// `boxes` with those of the same span across axis `axis` (0: x, 1: y) that touch or overlap
/// along it merged into one.
fn merged_along(mut boxes: Vec<CellBox>, axis: usize) -> Vec<CellBox> {
    let (low, high, across_low, across_high) = (axis, axis + 2, 1 - axis, 3 - axis);
    boxes.sort_unstable_by_key(|b| (b[across_low], b[across_high], b[low]));
    let mut merged: Vec<CellBox> = Vec::with_capacity(boxes.len());
    for b in boxes {
        match merged.last_mut() {
            Some(m)
                if m[across_low] == b[across_low]
                    && m[across_high] == b[across_high]
                    && b[low] <= m[high] + 1 =>
            {
                m[high] = m[high].max(b[high])
            }
            _ => merged.push(b),
        }
    }
    merged
}

impl WallBoxes {
    /// The boxes `boxes`, which together hold exactly the wall cells, merged: boxes of the same
    /// rows in touching columns (a drawn line's cells), then of the same columns in touching
    /// rows (a bitmap's pixel rows into walls). The merged boxes hold the same cells.
    pub(super) fn new(mut boxes: Vec<CellBox>) -> WallBoxes {
        boxes.retain(|b| b[0] <= b[2] && b[1] <= b[3]);
        let merged = merged_along(merged_along(boxes, 0), 1);
        let Some(low) = merged
            .iter()
            .map(|b| (b[0], b[1]))
            .reduce(|a, b| (a.0.min(b.0), a.1.min(b.1)))
        else {
            return WallBoxes::default();
        };
        let high = merged
            .iter()
            .fold(low, |a, b| (a.0.max(b[2]), a.1.max(b[3])));
        let columns = (high.0 - low.0) / BUCKET + 1;
        let rows = (high.1 - low.1) / BUCKET + 1;
        let mut walls = WallBoxes {
            boxes: Vec::new(),
            first: low,
            columns,
            rows,
            starts: vec![0; (columns * rows + 1) as usize],
            members: Vec::new(),
        };
        // A counting sort of (bucket, box) pairs, boxes in order within each bucket.
        let buckets: Vec<Vec<usize>> = merged.iter().map(|b| walls.buckets_of(b)).collect();
        for &k in buckets.iter().flatten() {
            walls.starts[k + 1] += 1;
        }
        for k in 0..walls.starts.len() - 1 {
            walls.starts[k + 1] += walls.starts[k];
        }
        let mut next = walls.starts.clone();
        walls.members = vec![0; walls.starts[walls.starts.len() - 1] as usize];
        for (i, of_box) in buckets.iter().enumerate() {
            for &k in of_box {
                walls.members[next[k] as usize] = i as u32;
                next[k] += 1;
            }
        }
        walls.boxes = merged;
        walls
    }

    /// The bucket columns and rows (inclusive, clamped to the grid) over cells `low..=high`.
    fn bucket_span(&self, low: (i64, i64), high: (i64, i64)) -> ((i64, i64), (i64, i64)) {
        let column = |v: i64| ((v - self.first.0).div_euclid(BUCKET)).clamp(0, self.columns - 1);
        let row = |v: i64| ((v - self.first.1).div_euclid(BUCKET)).clamp(0, self.rows - 1);
        ((column(low.0), row(low.1)), (column(high.0), row(high.1)))
    }

    /// How many boxes there are.
    /// Every box, merged.
    pub(super) fn all(&self) -> &[CellBox] {
        &self.boxes
    }

    pub(super) fn len(&self) -> usize {
        self.boxes.len()
    }

    /// Calls `f` once with each box that holds a cell of `low..=high` (global cells).
    pub(super) fn each_within(
        &self,
        low: (i64, i64),
        high: (i64, i64),
        mut f: impl FnMut(&CellBox),
    ) {
        if self.boxes.is_empty() {
            return;
        }
        let ((c0, r0), (c1, r1)) = self.bucket_span(low, high);
        for r in r0..=r1 {
            for c in c0..=c1 {
                let k = (r * self.columns + c) as usize;
                for &i in &self.members[self.starts[k] as usize..self.starts[k + 1] as usize] {
                    let b = &self.boxes[i as usize];
                    // Each box once: in the first bucket of the span that lists it.
                    let ((bc, br), _) = self.bucket_span((b[0], b[1]), (b[2], b[3]));
                    let meets = b[0] <= high.0 && b[2] >= low.0 && b[1] <= high.1 && b[3] >= low.1;
                    if bc.max(c0) == c && br.max(r0) == r && meets {
                        f(b);
                    }
                }
            }
        }
    }

    /// How many boxes the buckets over cells `low..=high` list, a box once per bucket: what
    /// reading the boxes within costs.
    pub(super) fn listed_within(&self, low: (i64, i64), high: (i64, i64)) -> usize {
        if self.boxes.is_empty() {
            return 0;
        }
        let ((c0, r0), (c1, r1)) = self.bucket_span(low, high);
        let listed = |r: i64| {
            let row = r * self.columns;
            (self.starts[(row + c1 + 1) as usize] - self.starts[(row + c0) as usize]) as usize
        };
        (r0..=r1).map(listed).sum()
    }

    /// The buckets box `b` lies in.
    fn buckets_of(&self, b: &CellBox) -> Vec<usize> {
        let ((c0, r0), (c1, r1)) = self.bucket_span((b[0], b[1]), (b[2], b[3]));
        (r0..=r1)
            .flat_map(|r| (c0..=c1).map(move |c| (r * self.columns + c) as usize))
            .collect()
    }
}
