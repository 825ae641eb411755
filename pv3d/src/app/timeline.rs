//! The replay timeline: when a server offers a `log` device driven by `readlog` (a
//! `player-sim --replay`, or real Player playing a log), a row to play, pause, rewind, step,
//! change speed and scrub. Play, pause and rewind are Player's own `log` requests, so they
//! work against real Player too; speed, seek, step and the position come from the replay's
//! extension of the interface (`player_proto::interfaces::log`).

use std::sync::Arc;

use eframe::egui::{self, Ui};
use player_proto::body_kind::BodyKind;
use player_proto::client::{Client, ConnectionState};
use player_proto::interfaces::log::{
    self, Log, LogPlayback, LogReadStep, LogSetReadPosition, LogSetReadSpeed, LogSetReadState,
};
use player_proto::message::Body;
use player_proto::wire::{DevAddr, Interface};

use crate::robots::RobotManager;

/// The driver name of a device that plays a log back (Player's and the replay's).
const READLOG: &str = "readlog";
/// Speeds offered, recorded seconds per real second.
const SPEEDS: [f64; 7] = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0];
/// One press of "step": this much recording (a tenth of a second: one sensor period of a
/// typical Stage world).
const STEP_SECONDS: f64 = 0.1;

/// The timeline's state: which server's `log` device it drives.
#[derive(Default)]
pub struct Timeline {
    device: Option<(Arc<Client>, DevAddr)>,
}

impl Timeline {
    /// Finds a replay among the servers; true when there is one.
    fn find(&mut self, robots: &RobotManager) -> bool {
        if self.device.is_some() {
            return true;
        }
        for (_, _, client) in robots.clients() {
            if client.state() != ConnectionState::Connected {
                continue;
            }
            let log = client
                .devices()
                .into_iter()
                .find(|d| d.addr.interf == Interface::LOG && d.driver == READLOG);
            if let Some(log) = log {
                let addr = client.addr(Interface::LOG, log.addr.index);
                // Subscribed for the position reports; kept across reconnections.
                drop(client.subscribe_async(addr));
                self.device = Some((client.clone(), addr));
                return true;
            }
        }
        false
    }

    /// The timeline row, if a server is a replay.
    pub fn ui(&mut self, ui: &mut Ui, robots: &RobotManager) {
        if !self.find(robots) {
            return;
        }
        let Some((client, addr)) = &self.device else {
            return;
        };
        let playback = client.latest_of::<LogPlayback>(*addr).map(|(p, _)| p);
        let ask = |subtype, body| drop(client.request_async(*addr, subtype, body));
        ui.horizontal(|ui| {
            ui.label(format!("Replay {}:{}", client.host(), client.port()));
            if ui.button("Rewind").clicked() {
                ask(log::REQ_SET_READ_REWIND, Body::Empty);
            }
            let playing = playback.is_some_and(|p| p.state != 0);
            // Words, not media symbols: egui's default fonts have no glyphs for those.
            if ui.button(if playing { "Pause" } else { "Play" }).clicked() {
                let state = LogSetReadState {
                    state: u8::from(!playing),
                };
                ask_with(client, *addr, Log::REQ_SET_READ_STATE, state);
            }
            let Some(playback) = playback else {
                ui.label("(this server reports no position: play, pause and rewind only)");
                return;
            };
            if ui.button("Step").on_hover_text("0.1 s further").clicked() {
                let step = LogReadStep {
                    seconds: STEP_SECONDS,
                };
                ask_with(client, *addr, Log::REQ_READ_STEP, step);
            }
            speed_menu(ui, &playback, |speed| {
                ask_with(
                    client,
                    *addr,
                    Log::REQ_SET_READ_SPEED,
                    LogSetReadSpeed { speed },
                );
            });
            let mut position = playback.position;
            let slider = egui::Slider::new(&mut position, 0.0..=playback.duration.max(0.0))
                .show_value(false);
            if ui.add(slider).changed() {
                let seek = LogSetReadPosition { position };
                ask_with(client, *addr, Log::REQ_SET_READ_POSITION, seek);
            }
            ui.label(format!(
                "{:.1} / {:.1} s",
                playback.position, playback.duration
            ));
        });
    }
}

fn speed_menu(ui: &mut Ui, playback: &LogPlayback, mut set: impl FnMut(f64)) {
    egui::ComboBox::from_id_salt("replay-speed")
        .selected_text(format!("{}×", playback.speed))
        .show_ui(ui, |ui| {
            for speed in SPEEDS {
                if ui
                    .selectable_label(playback.speed == speed, format!("{speed}×"))
                    .clicked()
                {
                    set(speed);
                }
            }
        });
}

/// Sends a request of `kind` carrying `value`; the timeline does not wait for the reply (the
/// next playback report shows its effect).
fn ask_with<T>(client: &Client, addr: DevAddr, kind: BodyKind<T>, value: T) {
    drop(client.request_async(addr, kind.subtype(), kind.to_body(value)));
}
