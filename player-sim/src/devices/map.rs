//! A `mapfile` device: its info and tiles on request, no data, and a NACK for the vector map,
//! as Player's `mapfile` answers (it has none).

use player_proto::interfaces::map::Map;
use player_proto::message::{Body, Message};
use player_proto::server::Reply;

use super::asks;
use crate::mapfile::GridMap;

pub(super) fn answer(map: &GridMap, request: &Message) -> Reply {
    if asks(request, Map::REQ_GET_INFO) {
        return Reply::Ack(Body::Map(Map::Info(map.info())));
    }
    match &request.body {
        Body::Map(Map::Tile(asked)) if asks(request, Map::REQ_GET_DATA) => {
            match map.tile(asked.col, asked.row, asked.width, asked.height) {
                Some(tile) => Reply::Ack(Body::Map(Map::Tile(tile))),
                None => Reply::Nack,
            }
        }
        _ => Reply::Nack,
    }
}
