//! A camera's frames through a chain of kernels, for its window: the plugin hands each new
//! frame to the viewer as a [`FilteredPicture`] and shows what comes back. The chain is the
//! `<filter>` parameters (`framework::scene::filter_config`), radii in pixels.

use std::sync::Arc;

use framework::config::{ConfigValueError, PluginConfig};
use framework::plugin::PluginContext;
use framework::scene::filter_config::read_filter_chain;
use framework::scene::{
    FilterChain, FilteredPicture, NodeId, Object3D, PixelFormat, Pixels, ViewOutput,
};
use image::RgbaImage;

/// The chain, the node that carries the request, and the newest filtered frame.
pub struct FrameFilter {
    chain: FilterChain,
    node: NodeId,
    output: ViewOutput,
    shown: Option<(u64, Arc<RgbaImage>)>,
}

impl FrameFilter {
    /// The filter the configuration asks for; `None` without `<filter>` parameters.
    pub fn from_config(
        config: &PluginConfig,
        ctx: &mut PluginContext<'_>,
    ) -> Result<Option<FrameFilter>, ConfigValueError> {
        let chain = read_filter_chain(config, "filter", |pixels| pixels)?;
        if chain.is_empty() {
            return Ok(None);
        }
        let node = ctx
            .scene
            .add(Object3D::new(format!("{} filter", config.titled("camera"))));
        Ok(Some(FrameFilter {
            chain,
            node,
            output: ViewOutput::new(),
            shown: None,
        }))
    }

    /// Asks for `frame` (top row first) to be filtered.
    pub fn offer(&self, frame: &RgbaImage, ctx: &mut PluginContext<'_>) {
        let mut flipped = frame.clone();
        image::imageops::flip_vertical_in_place(&mut flipped);
        let (w, h) = flipped.dimensions();
        let Ok(pixels) = Pixels::new(w, h, PixelFormat::Rgba8, flipped.into_raw()) else {
            return;
        };
        if let Some(object) = ctx.scene.get_mut(self.node) {
            object.geometry.filtered = vec![FilteredPicture {
                pixels,
                filters: self.chain.clone(),
                output: self.output.clone(),
            }];
        }
    }

    /// The newest filtered frame, top row first, with a number that changes with it.
    pub fn latest(&mut self) -> Option<(u64, Arc<RgbaImage>)> {
        let pixels = self.output.latest()?;
        if self.shown.as_ref().map(|s| s.0) != Some(pixels.generation()) {
            let mut image =
                RgbaImage::from_raw(pixels.width(), pixels.height(), pixels.bytes().to_vec())?;
            image::imageops::flip_vertical_in_place(&mut image);
            self.shown = Some((pixels.generation(), Arc::new(image)));
        }
        self.shown.clone()
    }

    /// The chain in words for the window's title line, in characters egui's font has (it
    /// lacks the arrow the chain's own description uses).
    pub fn describe(&self) -> String {
        self.chain.describe().replace('→', "then")
    }

    pub fn node(&self) -> NodeId {
        self.node
    }
}
