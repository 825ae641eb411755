//! The robots' status: each server's connection state, each used device's message rate and
//! the age of its newest data — so a person sees freshness and lag at a glance — and the
//! devices whose plugins wait for them to come back, and a note on a battery running low.

use std::collections::HashMap;
use std::time::{Duration, Instant};

use eframe::egui::{self, Color32, Ui};
use player_proto::client::{Client, ConnectionState};
use player_proto::interfaces::kind::MessageKind;
use player_proto::interfaces::power::Power;
use player_proto::message::Body;
use player_proto::wire::{DevAddr, Interface};

use super::device_gone::{GONE, GONE_COLOR};
use super::listing;
use crate::composition::FoundDevice;
use crate::robots::RobotManager;

const LOW_BATTERY_COLOR: Color32 = Color32::from_rgb(230, 80, 60);

/// Rates are computed over windows of this length.
const RATE_WINDOW: Duration = Duration::from_secs(1);

/// What the person is looking for in the panel.
pub struct Find<'a> {
    /// What they typed: rows whose host:port, state or devices hold every word are listed.
    pub text: &'a str,
    /// Servers listed whatever the text: those of the components it found.
    pub servers: &'a [(String, u16)],
    /// The selected robot's server, listed first.
    pub selected: Option<(&'a str, u16)>,
}

#[derive(Default)]
pub struct StatusPanel {
    /// (host, port, device) -> (messages at window start, window start, last rate)
    rates: HashMap<(String, u16, DevAddr), (u64, Instant, f64)>,
    /// Play, pause and scrub, when a server is a replay.
    timeline: super::timeline::Timeline,
}

impl StatusPanel {
    /// A summary line, then one row per server. Only the rows in sight are built, so a swarm
    /// of hundreds of servers costs a screenful of rows per frame, not hundreds. `gone`: the
    /// devices a server no longer lists while plugins wait for them.
    /// `find`: which rows to list, and which first.
    pub fn ui(&mut self, ui: &mut Ui, robots: &RobotManager, gone: &[FoundDevice], find: &Find) {
        let selected = find.selected;
        self.timeline.ui(ui, robots);
        let now = Instant::now();
        let mut clients: Vec<_> = robots.clients().collect();
        let total = clients.len();
        let connected = clients
            .iter()
            .filter(|(_, _, c)| c.state() == ConnectionState::Connected)
            .count();
        let used = robots.used_devices();
        if !find.text.trim().is_empty() {
            clients.retain(|&(host, port, client)| {
                if find.servers.iter().any(|(h, p)| h == host && *p == port) {
                    return true;
                }
                let devices: Vec<String> = used
                    .iter()
                    .filter(|(h, p, _)| h == host && *p == port)
                    .map(|(_, _, a)| format!("{}:{}", a.interf, a.index))
                    .collect();
                let text = format!("{host}:{port} {} {}", client.state(), devices.join(" "));
                listing::matches(find.text, &text)
            });
        }
        // Stable: the selected robot's server first, the others in their order.
        clients.sort_by_key(|&(host, port, _)| Some((host, port)) != selected);
        let shown = if clients.len() == total {
            String::new()
        } else {
            format!("; {} found", listing::thousands(clients.len()))
        };
        ui.label(format!(
            "{} Player servers: {} connected, {} not{shown}",
            listing::thousands(total),
            listing::thousands(connected),
            listing::thousands(total - connected)
        ));
        let row_height = ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
        egui::ScrollArea::vertical()
            .auto_shrink([false, true])
            .show_rows(ui, row_height, clients.len(), |ui, rows| {
                egui::Grid::new("robot-status")
                    .striped(true)
                    .show(ui, |ui| {
                        for &(host, port, client) in &clients[rows] {
                            self.row(ui, now, (host, port), client, &used, gone);
                            ui.end_row();
                        }
                    });
            });
    }

    fn row(
        &mut self,
        ui: &mut Ui,
        now: Instant,
        (host, port): (&str, u16),
        client: &Client,
        used: &[(String, u16, DevAddr)],
        gone: &[FoundDevice],
    ) {
        let state = client.state();
        let color = match state {
            ConnectionState::Connected => Color32::from_rgb(110, 200, 120),
            ConnectionState::Failed(_) => Color32::from_rgb(230, 90, 80),
            _ => Color32::from_rgb(230, 190, 80),
        };
        ui.colored_label(color, format!("{host}:{port}"));
        // Why it is not connected: a failed state says so itself; a reconnecting one does not.
        let state_text = match (&state, client.last_disconnect()) {
            (ConnectionState::Reconnecting { .. }, Some(why)) => format!("{state}: {why}"),
            _ => state.to_string(),
        };
        ui.colored_label(color, state_text);
        let mut cells = Vec::new();
        let mut notes = Vec::new();
        for (_, _, addr) in used.iter().filter(|(h, p, _)| h == host && *p == port) {
            let count = client.stats(*addr).updates;
            let entry = self
                .rates
                .entry((host.to_string(), port, *addr))
                .or_insert((count, now, 0.0));
            let elapsed = now.duration_since(entry.1);
            if elapsed >= RATE_WINDOW {
                entry.2 = (count - entry.0) as f64 / elapsed.as_secs_f64();
                *entry = (count, now, entry.2);
            }
            let age = MessageKind::data_of(addr.interf)
                .filter_map(|kind| client.latest(*addr, kind.subtype))
                .map(|s| now.saturating_duration_since(s.received))
                .min();
            let age = age.map_or("no data".to_string(), |a| {
                format!("{:.1} s", a.as_secs_f32())
            });
            cells.push(format!(
                "{}:{} {:.0} Hz, {age}",
                addr.interf, addr.index, entry.2
            ));
            notes.extend(battery_note(client, *addr));
        }
        let gone_here: Vec<String> = gone
            .iter()
            .filter(|d| d.host == host && d.port == port)
            .map(|d| format!("{}:{} {GONE}", d.addr.interf, d.addr.index))
            .collect();
        ui.horizontal(|ui| {
            ui.label(cells.join("   "));
            if !gone_here.is_empty() {
                ui.colored_label(GONE_COLOR, gone_here.join("   "));
            }
            if !notes.is_empty() {
                ui.colored_label(LOW_BATTERY_COLOR, notes.join("   "));
            }
        });
    }
}

/// A power device's "battery low" note, by the power plugin's default threshold.
fn battery_note(client: &Client, addr: DevAddr) -> Option<String> {
    if addr.interf != Interface::POWER {
        return None;
    }
    let newest = client.latest(addr, Power::DATA_STATE.subtype())?;
    match newest.message.body {
        Body::Power(Power::State(data)) => plugins::power::low_note(&data),
        _ => None,
    }
}
