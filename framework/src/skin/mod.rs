//! OBJ skins (`skinFile`): a model drawn in place of a device's box body. The shared
//! [`MeshManager`] loads each file once, however many robots wear it, and counts its users;
//! the mesh is freed when the last one goes.
//!
//! A skin is fitted into the body's box (see [`fit_into`]): the OBJ's +x is the front, +z up,
//! and its extent is stretched to the device's size, so any model of any unit fits.

mod fit;

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock, Weak};

use glam::Vec3;

pub use fit::fit_into;

/// The largest OBJ file read, bytes: a skin is a small model, not a scan of a building.
pub const MAX_FILE_BYTES: u64 = 16 * 1024 * 1024;
/// The most triangles a skin may have.
pub const MAX_TRIANGLES: usize = 200_000;

/// A loaded OBJ model: its triangles and their bounds.
#[derive(Debug, PartialEq)]
pub struct SkinMesh {
    pub path: PathBuf,
    pub triangles: Vec<[Vec3; 3]>,
    pub min: Vec3,
    pub max: Vec3,
}

/// Why a skin could not be used (the plugin draws its box body instead).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SkinError {
    #[error("skin {path}: cannot read it: {message}")]
    Unreadable { path: String, message: String },
    #[error("skin {path}: {bytes} bytes is more than the {MAX_FILE_BYTES} a skin may have")]
    TooLarge { path: String, bytes: u64 },
    #[error("skin {path}: not a usable OBJ model: {message}")]
    Malformed { path: String, message: String },
}

/// The meshes loaded so far, by file, each alive while someone uses it.
#[derive(Default)]
pub struct MeshManager {
    meshes: Mutex<HashMap<PathBuf, Weak<SkinMesh>>>,
    /// How many times each file was read (once, while it has users).
    reads: Mutex<HashMap<PathBuf, usize>>,
}

impl MeshManager {
    /// The manager every plugin of the program shares.
    pub fn shared() -> &'static MeshManager {
        static SHARED: OnceLock<MeshManager> = OnceLock::new();
        SHARED.get_or_init(MeshManager::default)
    }

    /// The mesh of `path`, loaded now or shared with its other users. Keep the `Arc` while the
    /// skin is drawn: it is the user count.
    pub fn acquire(&self, path: &Path) -> Result<Arc<SkinMesh>, SkinError> {
        let key = path.canonicalize().map_err(|e| SkinError::Unreadable {
            path: path.display().to_string(),
            message: e.to_string(),
        })?;
        let mut meshes = self.meshes.lock().expect("mesh manager");
        if let Some(mesh) = meshes.get(&key).and_then(Weak::upgrade) {
            return Ok(mesh);
        }
        let mesh = Arc::new(load_obj(&key)?);
        *self
            .reads
            .lock()
            .expect("mesh manager")
            .entry(key.clone())
            .or_default() += 1;
        meshes.retain(|_, weak| weak.strong_count() > 0);
        meshes.insert(key, Arc::downgrade(&mesh));
        Ok(mesh)
    }

    /// How many users the mesh of `path` has now (0 when it is not loaded).
    pub fn users(&self, path: &Path) -> usize {
        let Ok(key) = path.canonicalize() else {
            return 0;
        };
        let meshes = self.meshes.lock().expect("mesh manager");
        meshes.get(&key).map_or(0, Weak::strong_count)
    }

    /// How many times `path` was read from disk.
    pub fn reads(&self, path: &Path) -> usize {
        let Ok(key) = path.canonicalize() else {
            return 0;
        };
        self.reads
            .lock()
            .expect("mesh manager")
            .get(&key)
            .copied()
            .unwrap_or(0)
    }
}

/// Reads an OBJ file (every object in it, triangulated; materials are not used).
fn load_obj(path: &Path) -> Result<SkinMesh, SkinError> {
    let shown = path.display().to_string();
    let bytes = std::fs::metadata(path)
        .map_err(|e| SkinError::Unreadable {
            path: shown.clone(),
            message: e.to_string(),
        })?
        .len();
    if bytes > MAX_FILE_BYTES {
        return Err(SkinError::TooLarge { path: shown, bytes });
    }
    let malformed = |message: String| SkinError::Malformed {
        path: shown.clone(),
        message,
    };
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _materials) =
        tobj::load_obj(path, &options).map_err(|e| malformed(e.to_string()))?;
    let mut triangles = Vec::new();
    for model in &models {
        let m = &model.mesh;
        let vertex = |i: u32| -> Option<Vec3> {
            let i = i as usize * 3;
            Some(Vec3::new(
                *m.positions.get(i)?,
                *m.positions.get(i + 1)?,
                *m.positions.get(i + 2)?,
            ))
        };
        for face in m.indices.chunks_exact(3) {
            if triangles.len() >= MAX_TRIANGLES {
                return Err(malformed(format!("more than {MAX_TRIANGLES} triangles")));
            }
            let corners = [vertex(face[0]), vertex(face[1]), vertex(face[2])];
            let [Some(a), Some(b), Some(c)] = corners else {
                return Err(malformed(format!(
                    "object {:?} has a face with a vertex index past its {} vertices",
                    model.name,
                    m.positions.len() / 3
                )));
            };
            if !(a.is_finite() && b.is_finite() && c.is_finite()) {
                return Err(malformed(format!(
                    "object {:?} has a vertex that is not a finite number",
                    model.name
                )));
            }
            triangles.push([a, b, c]);
        }
    }
    if triangles.is_empty() {
        return Err(malformed("no faces".into()));
    }
    let all = triangles.iter().flatten();
    let min = all.clone().fold(Vec3::splat(f32::MAX), |m, p| m.min(*p));
    let max = all.fold(Vec3::splat(f32::MIN), |m, p| m.max(*p));
    Ok(SkinMesh {
        path: path.to_path_buf(),
        triangles,
        min,
        max,
    })
}

/// A plugin's `skinFile`: the mesh while the plugin wears it, or why it does not.
#[derive(Debug, Default)]
pub struct Skin {
    pub mesh: Option<Arc<SkinMesh>>,
    /// Shown in the item tree: the file is missing or broken, the box body is drawn.
    pub error: Option<String>,
}

impl Skin {
    /// The skin `config`'s `skinFile` names (relative to the composition), if any.
    pub fn from_config(config: &crate::config::PluginConfig) -> Skin {
        let (Some(param), Some(path)) = (config.param("skinFile"), config.path("skinFile")) else {
            return Skin::default();
        };
        match MeshManager::shared().acquire(&path) {
            Ok(mesh) => Skin {
                mesh: Some(mesh),
                error: None,
            },
            Err(e) => {
                let origin = if param.origin.is_empty() {
                    &config.origin
                } else {
                    &param.origin
                };
                let message = format!(
                    "{origin}: <skinFile> of {}: {e}; drawing the box body",
                    config.library
                );
                tracing::error!("{message}");
                Skin {
                    mesh: None,
                    error: Some(message),
                }
            }
        }
    }

    /// The error, in red, when there is one.
    pub fn ui(&self, ui: &mut egui::Ui) {
        if let Some(error) = &self.error {
            ui.colored_label(egui::Color32::from_rgb(230, 90, 80), error);
        }
    }
}
