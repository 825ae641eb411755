//! The rendered view served as a Player `camera` device, so that any Player client — a
//! vision program, `playercam` — sees the simulated camera as it would a real one: the paper's
//! "mixing a real and a simulated world". Frames go out raw (RGB888, top row first, as Stage's
//! cameras send them) to whoever subscribed.

use std::time::{SystemTime, UNIX_EPOCH};

use framework::scene::{PixelFormat, Pixels};
use player_proto::DevAddr;
use player_proto::interfaces::camera::{COMPRESS_RAW, Camera, CameraData, FORMAT_RGB888};
use player_proto::message::Body;
use player_proto::server::{Device, Server, ServerConfig, ServerError};

/// The driver name clients see in the device list.
pub const DRIVER_NAME: &str = "pv3d_virtual_camera";
/// RGB888: three bytes, 24 bits a pixel.
const RGB_BYTES: usize = 3;
const RGB_BITS: u32 = 24;

/// The device behind the port: it only publishes, so it answers every request with a NACK.
struct RenderedCamera;

impl Device for RenderedCamera {
    fn driver_name(&self) -> &str {
        DRIVER_NAME
    }

    fn accepts_commands(&self) -> bool {
        false
    }
}

/// A Player server with one `camera:0` device fed by the virtual camera.
pub struct CameraServer {
    server: Server,
    addr: DevAddr,
}

impl CameraServer {
    /// Listens on `port` (0: any free one) on the loopback address.
    pub fn start(port: u16) -> Result<CameraServer, ServerError> {
        let mut config = ServerConfig::default();
        config.thread_name = "pv3d-virtual-camera".into();
        let robot = config.robot(port);
        let addr: DevAddr = "camera:0".parse().expect("a fixed, valid address");
        config.device(robot, addr, RenderedCamera);
        let server = Server::start(config)?;
        let addr = DevAddr {
            robot: u32::from(server.port(robot)),
            ..addr
        };
        Ok(CameraServer { server, addr })
    }

    /// The port it listens on.
    pub fn port(&self) -> u16 {
        self.server.port(0)
    }

    /// Sends a rendered picture to the subscribers; returns how many it reached.
    pub fn publish(&self, pixels: &Pixels) -> usize {
        if self.server.publisher().subscribers(self.addr) == 0 {
            return 0; // Converting a frame nobody wants is wasted work.
        }
        let timestamp = SystemTime::now()
            .duration_since(UNIX_EPOCH)
            .map_or(0.0, |d| d.as_secs_f64());
        self.server.publisher().publish(
            self.addr,
            Camera::DATA_STATE.subtype(),
            Body::Camera(Camera::State(camera_data(pixels))),
            timestamp,
        )
    }
}

/// A picture (rows bottom-up) as a raw Player frame (rows top-down, RGB).
pub fn camera_data(pixels: &Pixels) -> CameraData {
    let width = pixels.width() as usize;
    let row = width * pixels.format().bytes_per_pixel();
    let mut rgb = Vec::with_capacity(width * pixels.height() as usize * RGB_BYTES);
    for line in pixels.bytes().chunks_exact(row).rev() {
        match pixels.format() {
            PixelFormat::Rgba8 => {
                for p in line.chunks_exact(PixelFormat::Rgba8.bytes_per_pixel()) {
                    rgb.extend_from_slice(&p[..RGB_BYTES]);
                }
            }
            PixelFormat::Gray8 => {
                for &g in line {
                    rgb.extend_from_slice(&[g; RGB_BYTES]);
                }
            }
        }
    }
    CameraData {
        width: pixels.width(),
        height: pixels.height(),
        bpp: RGB_BITS,
        format: FORMAT_RGB888,
        fdiv: 0,
        compression: COMPRESS_RAW,
        image: rgb.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bottom_row_of_a_picture_is_the_last_row_of_a_frame() {
        let bytes = [[255, 0, 0, 255], [0, 0, 255, 255]].concat(); // 1 × 2: red below blue
        let pixels = Pixels::new(1, 2, PixelFormat::Rgba8, bytes).unwrap();
        let frame = camera_data(&pixels);
        assert_eq!(&frame.image[..], &[0, 0, 255, 255, 0, 0]);
        assert_eq!((frame.width, frame.height, frame.bpp), (1, 2, 24));
    }
}
