//! A robot's upstream subscriptions, counted: the relay subscribes to a device while anyone
//! wants it — a front's look ([`player_front::Watch`]), a Player observer, a front that
//! watches everything, the survey on each connection — and unsubscribes once nobody does, so
//! the robot's server computes and sends only what is watched.
//!
//! The upstream client keeps (and restores on every reconnection) a subscription once made,
//! and a real Player server registers a second subscription to the same device twice: so the
//! relay asks only on a device's first want and lets go only on its last, under one lock, in
//! order.

use std::collections::{BTreeSet, HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, OnceLock};

use player_front::{Device, Upstream};
use player_proto::client::Client;

#[derive(Default)]
struct State {
    /// Some front watches everything (it does not say what is looked at).
    everything: bool,
    /// The robot's devices, as the last survey found them.
    devices: Vec<Device>,
    /// Looks held by the fronts, per device.
    looks: HashMap<Device, usize>,
    /// Devices a Player observer subscribed to: kept until the relay stops (cheap next to
    /// reconnecting for the next observer).
    observed: HashSet<Device>,
    /// Devices the survey holds while it describes them and waits for their first data.
    surveying: HashSet<Device>,
    /// What the upstream client was asked to subscribe to.
    subscribed: BTreeSet<Device>,
}

impl State {
    fn wanted(&self, device: Device) -> bool {
        (self.everything && self.devices.contains(&device))
            || self.looks.get(&device).is_some_and(|n| *n > 0)
            || self.observed.contains(&device)
            || self.surveying.contains(&device)
    }
}

/// One robot's subscriptions; the fronts' [`player_front::Watch`] looks through it.
#[derive(Default)]
pub struct Subscriptions {
    client: OnceLock<Arc<Client>>,
    state: Mutex<State>,
    /// Whether a Player observer ever subscribed (read on every message: no lock).
    observed: AtomicBool,
}

impl Subscriptions {
    fn lock(&self) -> MutexGuard<'_, State> {
        // Every change is whole under the lock: a poisoned lock still guards a usable value.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The client that subscribes (set once, when the robot's client starts).
    pub(crate) fn set_client(&self, client: Arc<Client>) {
        let _ = self.client.set(client);
        let mut state = self.lock();
        let mut wanted: BTreeSet<Device> = state.looks.keys().copied().collect();
        wanted.extend(state.observed.iter().chain(&state.surveying));
        for device in wanted {
            self.settle(&mut state, device);
        }
    }

    /// Devices subscribed upstream now.
    pub fn subscribed(&self) -> Vec<Device> {
        self.lock().subscribed.iter().copied().collect()
    }

    /// Subscribes or unsubscribes `device` so that it is subscribed exactly while wanted.
    /// Never waits: the client's thread takes the request, its reply arrives later.
    fn settle(&self, state: &mut State, device: Device) {
        let Some(client) = self.client.get() else {
            // Before the client exists nothing is asked; `set_client` settles again.
            return;
        };
        let wanted = state.wanted(device);
        if wanted == state.subscribed.contains(&device) {
            return;
        }
        let addr = client.addr(device.0, device.1);
        if wanted {
            state.subscribed.insert(device);
            drop(client.subscribe_async(addr));
        } else {
            state.subscribed.remove(&device);
            drop(client.unsubscribe_async(addr));
        }
    }

    fn change(&self, device: Device, change: impl FnOnce(&mut State)) {
        let mut state = self.lock();
        change(&mut state);
        self.settle(&mut state, device);
    }

    /// Some front watches every device, for as long as the relay runs.
    pub(crate) fn watch_everything(&self) {
        let mut state = self.lock();
        state.everything = true;
        for device in state.devices.clone() {
            self.settle(&mut state, device);
        }
    }

    /// Whether a Player observer ever subscribed to one of the robot's devices.
    pub(crate) fn observed(&self) -> bool {
        self.observed.load(Ordering::Relaxed)
    }

    /// A Player observer subscribed to `device`.
    pub(crate) fn observe(&self, device: Device) {
        self.observed.store(true, Ordering::Relaxed);
        self.change(device, |state| {
            state.observed.insert(device);
        });
    }

    /// The survey found `devices` on this connection and holds them all until
    /// [`Subscriptions::surveyed`].
    pub(crate) fn survey(&self, devices: &[Device]) {
        let mut state = self.lock();
        state.devices = devices.to_vec();
        state.surveying = devices.iter().copied().collect();
        for &device in devices {
            self.settle(&mut state, device);
        }
    }

    /// The survey is over: what nobody looks at is let go.
    pub(crate) fn surveyed(&self) {
        let mut state = self.lock();
        let held: Vec<Device> = state.surveying.drain().collect();
        for device in held {
            self.settle(&mut state, device);
        }
    }
}

impl Upstream for Subscriptions {
    fn look(&self, device: Device) {
        self.change(device, |state| *state.looks.entry(device).or_default() += 1);
    }

    fn look_away(&self, device: Device) {
        self.change(device, |state| {
            if let Some(n) = state.looks.get_mut(&device) {
                *n = n.saturating_sub(1);
                if *n == 0 {
                    state.looks.remove(&device);
                }
            }
        });
    }
}
