//! Asking a `map` device for its grid: the info first, then the tiles, a few at a time so
//! that neither the link nor the server is flooded, each reply written into the grid as it
//! comes. Polled from the plugin's update; the UI thread never waits.

use std::collections::VecDeque;

use framework::device::{Awaited, DeviceAccess, PendingReply};
use player_proto::interfaces::map::{Map, MapData, MapInfo};

use super::grid::OccupancyGrid;

/// Tile requests sent before the first reply is waited for: enough to hide the round trip,
/// few enough that a 4000 × 4000 map (49 tiles) does not sit in one queue.
pub const TILES_IN_FLIGHT: usize = 4;

/// The most tile errors kept to show; all are logged.
const ERRORS_KEPT: usize = 5;

/// What one poll brought.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Polled {
    /// The info arrived and the grid was made (all unknown).
    pub info_arrived: bool,
    /// Tiles answered, written into the grid or not.
    pub tiles_answered: usize,
}

/// The fetch of one map, from the info request to the last tile.
pub struct MapFetch {
    info: Awaited<MapInfo>,
    grid: Option<OccupancyGrid>,
    waiting: VecDeque<MapData>,
    in_flight: VecDeque<(MapData, PendingReply)>,
    pub tiles_total: usize,
    pub tiles_received: usize,
    pub tiles_failed: usize,
    /// Why there is no map at all (the info was refused or made no sense).
    pub fatal: Option<String>,
    /// Why some tiles are missing (they stay unknown), the first few.
    pub tile_errors: Vec<String>,
}

impl MapFetch {
    /// Sends the info request.
    pub fn start(device: Option<&dyn DeviceAccess>) -> MapFetch {
        MapFetch {
            info: Awaited::fetch(device, Map::REQ_GET_INFO),
            grid: None,
            waiting: VecDeque::new(),
            in_flight: VecDeque::new(),
            tiles_total: 0,
            tiles_received: 0,
            tiles_failed: 0,
            fatal: None,
            tile_errors: Vec::new(),
        }
    }

    pub fn grid(&self) -> Option<&OccupancyGrid> {
        self.grid.as_ref()
    }

    /// Every tile answered, well or not.
    pub fn is_complete(&self) -> bool {
        self.grid.is_some() && self.waiting.is_empty() && self.in_flight.is_empty()
    }

    /// Takes the replies that arrived and sends the next requests.
    pub fn poll(&mut self, device: Option<&dyn DeviceAccess>) -> Polled {
        let mut polled = Polled::default();
        if let Some(outcome) = self.info.take() {
            match outcome
                .map_err(|e| e.to_string())
                .and_then(|info| OccupancyGrid::new(info).map_err(|e| e.to_string()))
            {
                Ok(grid) => {
                    self.waiting = grid.tiles().into();
                    self.tiles_total = self.waiting.len();
                    self.grid = Some(grid);
                    polled.info_arrived = true;
                }
                Err(e) => {
                    tracing::error!("no map: {e}");
                    self.fatal = Some(format!("no map: {e}"));
                }
            }
        }
        let Some(grid) = self.grid.as_mut() else {
            return polled;
        };
        // Replies come in the order asked; take those that are here.
        while let Some((rect, pending)) = self.in_flight.front() {
            let Some(outcome) = pending.try_get() else {
                break;
            };
            let (col, row) = (rect.col, rect.row);
            self.in_flight.pop_front();
            polled.tiles_answered += 1;
            let applied = outcome
                .and_then(|reply| Map::REQ_GET_DATA.reply_of(&reply))
                .map_err(|e| format!("the tile at column {col}, row {row}: {e}"))
                .and_then(|tile| grid.apply(&tile).map_err(|e| e.to_string()));
            match applied {
                Ok(()) => self.tiles_received += 1,
                Err(e) => {
                    tracing::warn!("map tile left unknown: {e}");
                    self.tiles_failed += 1;
                    if self.tile_errors.len() < ERRORS_KEPT {
                        self.tile_errors.push(e);
                    }
                }
            }
        }
        if let Some(device) = device {
            while self.in_flight.len() < TILES_IN_FLIGHT
                && let Some(rect) = self.waiting.pop_front()
            {
                let body = Map::REQ_GET_DATA.to_body(rect.clone());
                let pending = device.request(Map::REQ_GET_DATA.kind(), body);
                self.in_flight.push_back((rect, pending));
            }
        }
        polled
    }
}
