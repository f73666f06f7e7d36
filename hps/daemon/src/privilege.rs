//! Least privilege: the daemon needs root only to map the register window and the DMA
//! buffer (`/dev/mem` or `/dev/uioN`). Once both are mapped, the mappings stay valid after
//! the process gives up root, so it drops to an unprivileged user before it captures, parses
//! files or serves the network.
//!
//! Order (setgroups, setgid, setuid) matters: after setuid the process could no longer
//! change its groups. The drop is then checked: getting root back must fail.

/// Who the process is now.
#[derive(Debug, PartialEq, Eq)]
pub enum Dropped {
    /// Dropped from root to this uid/gid.
    To { uid: u32, gid: u32 },
    /// Not root to begin with: nothing to drop.
    NotRoot { uid: u32 },
}

/// Why root could not be dropped (fatal: the daemon refuses to run as root).
#[derive(Debug, thiserror::Error)]
pub enum PrivilegeError {
    #[error("user `{0}` does not exist (create it, or set hardware.user)")]
    NoUser(String),
    #[error("group `{0}` does not exist")]
    NoGroup(String),
    #[error("{call} failed: {source}")]
    Call {
        call: &'static str,
        source: std::io::Error,
    },
    #[error("root could be regained after dropping to uid {uid}: refusing to continue")]
    StillRoot { uid: u32 },
    #[error("dropping privileges is implemented for Linux only")]
    Unsupported,
}

/// Drops root to `user` (and `group`, default: the user's primary group).
#[cfg(target_os = "linux")]
pub fn drop_root(user: &str, group: Option<&str>) -> Result<Dropped, PrivilegeError> {
    use std::ffi::CString;
    // SAFETY (all libc calls below): plain system calls on integers, and the reentrant
    // lookups with buffers we own and sizes we pass.
    let uid_now = unsafe { libc::geteuid() };
    if uid_now != 0 {
        return Ok(Dropped::NotRoot { uid: uid_now });
    }
    let cuser = CString::new(user).map_err(|_| PrivilegeError::NoUser(user.into()))?;
    let mut pwd: libc::passwd = unsafe { std::mem::zeroed() };
    let mut result: *mut libc::passwd = std::ptr::null_mut();
    let mut buf = vec![0 as libc::c_char; 16 * 1024];
    let rc = unsafe {
        libc::getpwnam_r(
            cuser.as_ptr(),
            &mut pwd,
            buf.as_mut_ptr(),
            buf.len(),
            &mut result,
        )
    };
    if rc != 0 || result.is_null() {
        return Err(PrivilegeError::NoUser(user.into()));
    }
    let (uid, mut gid) = (pwd.pw_uid, pwd.pw_gid);
    if let Some(g) = group {
        let cgroup = CString::new(g).map_err(|_| PrivilegeError::NoGroup(g.into()))?;
        let mut grp: libc::group = unsafe { std::mem::zeroed() };
        let mut result: *mut libc::group = std::ptr::null_mut();
        let rc = unsafe {
            libc::getgrnam_r(
                cgroup.as_ptr(),
                &mut grp,
                buf.as_mut_ptr(),
                buf.len(),
                &mut result,
            )
        };
        if rc != 0 || result.is_null() {
            return Err(PrivilegeError::NoGroup(g.into()));
        }
        gid = grp.gr_gid;
    }
    let call = |name: &'static str, rc: libc::c_int| {
        if rc == 0 {
            Ok(())
        } else {
            Err(PrivilegeError::Call {
                call: name,
                source: std::io::Error::last_os_error(),
            })
        }
    };
    call("setgroups", unsafe { libc::setgroups(1, &gid) })?;
    call("setgid", unsafe { libc::setgid(gid) })?;
    call("setuid", unsafe { libc::setuid(uid) })?;
    if uid != 0 && unsafe { libc::setuid(0) } == 0 {
        return Err(PrivilegeError::StillRoot { uid });
    }
    Ok(Dropped::To { uid, gid })
}

#[cfg(not(target_os = "linux"))]
pub fn drop_root(_user: &str, _group: Option<&str>) -> Result<Dropped, PrivilegeError> {
    Err(PrivilegeError::Unsupported)
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;

    #[test]
    fn unknown_user_is_refused_or_not_root() {
        match drop_root("no-such-user-skyluxd", None) {
            Err(PrivilegeError::NoUser(u)) => assert_eq!(u, "no-such-user-skyluxd"),
            Ok(Dropped::NotRoot { uid }) => assert_ne!(uid, 0),
            other => panic!("{other:?}"),
        }
    }

    /// The real drop, in a child process (this test binary again, running only
    /// `child_drops_to_nobody`), so the test runner keeps its root.
    #[test]
    fn drop_in_child_when_root() {
        if !skylux_hps::prerequisite::available_or_skip(
            unsafe { libc::geteuid() } == 0,
            skylux_hps::prerequisite::REQUIRE_HOST,
            "not root: the privilege drop cannot be tried",
        ) {
            return;
        }
        let exe = std::env::current_exe().unwrap();
        let mut cmd = crate::spawn::command_for(&exe);
        cmd.args([
            "--exact",
            "privilege::tests::child_drops_to_nobody",
            "--ignored",
            "--nocapture",
        ])
        .env("SKYLUXD_DROP_CHILD", "1");
        let out = cmd.output().unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{text}{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(text.contains("dropped to uid"), "{text}");
    }

    /// Run only by `drop_in_child_when_root`, in its child (it gives up root for good).
    #[test]
    #[ignore = "the child half of drop_in_child_when_root"]
    fn child_drops_to_nobody() {
        assert!(
            std::env::var_os("SKYLUXD_DROP_CHILD").is_some(),
            "run by drop_in_child_when_root only: it drops this process's root"
        );
        match drop_root("nobody", None).unwrap() {
            Dropped::To { uid, .. } => {
                assert_ne!(uid, 0);
                assert_eq!(unsafe { libc::geteuid() }, uid);
                // Root files are now out of reach.
                assert!(std::fs::File::create("/root/.skyluxd-must-not-exist").is_err());
                println!("dropped to uid {uid}");
            }
            other => panic!("{other:?}"),
        }
    }
}
