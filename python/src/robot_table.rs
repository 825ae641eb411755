//! A `Robot` in Jupyter: a table of its devices and how fresh their data is.

use player_proto::client::DeviceStats;
use pyo3::PyResult;

use crate::link::Link;

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Freshness of one device: how long ago its newest data arrived, or that none did (a
/// device is only sent data while something subscribed to it).
fn freshness(link: &Link, addr: player_proto::wire::DevAddr) -> String {
    let newest = link
        .client
        .newest_data()
        .into_iter()
        .filter(|s| s.message.header.addr.interf == addr.interf)
        .filter(|s| s.message.header.addr.index == addr.index)
        .map(|s| s.received.elapsed())
        .min();
    match newest {
        Some(age) => format!("{:.2} s ago", age.as_secs_f64()),
        None => "—".into(),
    }
}

pub fn html(link: &Link) -> PyResult<String> {
    let mut rows = String::new();
    for d in link.client.devices() {
        let DeviceStats { messages, .. } = link.client.stats(d.addr);
        rows.push_str(&format!(
            "<tr><td>{}:{}</td><td>{}</td><td>{messages}</td><td>{}</td></tr>",
            d.addr.interf.name().unwrap_or("?"),
            d.addr.index,
            escape(&d.driver),
            freshness(link, d.addr)
        ));
    }
    let state = if link.is_connected() {
        "connected"
    } else {
        "not connected"
    };
    Ok(format!(
        "<b>Robot {}</b> ({state})<table><tr><th>device</th><th>driver</th>\
         <th>messages</th><th>newest</th></tr>{rows}</table>",
        escape(&link.place)
    ))
}
