//! `--zenoh` and `--from-zenoh`: the relay's robots published into Zenoh, and robots found in
//! Zenoh served as Player servers (see the `player_zenoh` crate for the key space and the
//! control rule).

use std::net::IpAddr;
use std::path::PathBuf;
use std::sync::Arc;

use anyhow::{Context, Result};
use clap::Args;
use player_proto::server::Commanders;
use player_zenoh::{FromZenoh, FromZenohConfig, FrontConfig, Mode, ZenohFront, ZenohOptions};
use tokio::runtime::Handle;

#[derive(Args, Debug)]
pub struct ZenohArgs {
    /// Publish every relayed robot into Zenoh, under player/SITE/HOST_PORT/….
    #[arg(long)]
    pub zenoh: bool,

    /// Serve the robots found in Zenoh (on --site, every site by default) as Player servers
    /// on --bind; no robot needed on the command line.
    #[arg(long)]
    pub from_zenoh: bool,

    /// The site: the second chunk of every key.
    #[arg(long, value_name = "NAME")]
    pub site: Option<String>,

    /// With --zenoh: the identity whose commands reach the robots (sent by a
    /// --from-zenoh relay started with --zenoh-id ID); nobody's by default.
    #[arg(long, value_name = "ID")]
    pub zenoh_controller: Option<String>,

    /// With --from-zenoh: the identity sent with commands (default: this Zenoh session's id).
    #[arg(long, value_name = "ID")]
    pub zenoh_id: Option<String>,

    /// With --from-zenoh: serve the n-th robot found on PORT + n (default: free ports).
    #[arg(long, value_name = "PORT", default_value_t = 0)]
    pub zenoh_base_port: u16,

    /// Zenoh mode: peer, client or router.
    #[arg(long, value_name = "MODE")]
    pub zenoh_mode: Option<Mode>,

    /// A Zenoh endpoint to connect to, e.g. tcp/192.168.1.10:7447 (repeatable).
    #[arg(long, value_name = "ENDPOINT")]
    pub zenoh_connect: Vec<String>,

    /// A Zenoh endpoint to listen on, e.g. tcp/0.0.0.0:7447 (repeatable).
    #[arg(long, value_name = "ENDPOINT")]
    pub zenoh_listen: Vec<String>,

    /// Zenoh's own JSON5 configuration file; the options above amend it.
    #[arg(long, value_name = "FILE")]
    pub zenoh_config: Option<PathBuf>,
}

/// The Zenoh side of a running relay.
#[derive(Default)]
pub struct Zenoh {
    pub front: Option<Arc<ZenohFront>>,
    pub bridge: Option<FromZenoh>,
}

impl ZenohArgs {
    fn wanted(&self) -> bool {
        self.zenoh || self.from_zenoh
    }

    /// Whether the relay's upstream clients must take commands from the front.
    pub fn fronts_command(&self) -> bool {
        self.zenoh && self.zenoh_controller.is_some()
    }

    /// Opens the session and starts what was asked; the front on `runtime`, the fronts' one.
    pub fn start(&self, runtime: &Handle, bind: IpAddr, commanders: Commanders) -> Result<Zenoh> {
        if !self.wanted() {
            return Ok(Zenoh::default());
        }
        let options = ZenohOptions {
            config_file: self.zenoh_config.clone(),
            mode: self.zenoh_mode,
            connect: self.zenoh_connect.clone(),
            listen: self.zenoh_listen.clone(),
            no_scouting: false,
            // A relay started before its router (or its peer) waits for it.
            connect_patience: Some(std::time::Duration::MAX),
        };
        if !self.zenoh_connect.is_empty() {
            eprintln!(
                "Zenoh: joining through {} (waiting until it answers)",
                self.zenoh_connect.join(", ")
            );
        }
        let session = options.open().context("cannot join Zenoh")?;
        let mut zenoh = Zenoh::default();
        if self.zenoh {
            let site = self.site.as_deref().unwrap_or("default");
            let config = FrontConfig {
                controller: self.zenoh_controller.clone(),
                ..FrontConfig::new(site)
            };
            zenoh.front = Some(Arc::new(ZenohFront::start_on(
                runtime.clone(),
                session.clone(),
                config,
            )?));
            eprintln!("Zenoh: publishing the robots under player/{site}/");
        }
        if self.from_zenoh {
            let site = self.site.as_deref().unwrap_or("*");
            let identity = match &self.zenoh_id {
                Some(id) => id.clone(),
                None => session.zid().to_string(),
            };
            let config = FromZenohConfig {
                bind,
                base_port: self.zenoh_base_port,
                commanders,
                ..FromZenohConfig::new(site, &identity)
            };
            zenoh.bridge = Some(FromZenoh::start(session, config)?);
            eprintln!("Zenoh: serving the robots of player/{site}/ on {bind}, as {identity}");
        }
        Ok(zenoh)
    }
}
