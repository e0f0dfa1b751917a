!> Restart dumps of MPI runs (issue 7, last acceptance item; docs/history.md "Restart of MPI
!> runs"). A dump set of an NP-rank run is NP part files and one manifest:
!>   <stem>.cycC.rankRRRRR.h5  each rank's sub-model state at cycle C, written by the
!>                         serial writer (dx_restart: restart_write on the rank's model_t, so
!>                         components that dump themselves there - rigid bodies, contact -
!>                         are in the part too), atomically: <part>.tmp, fsync, rename;
!>   <stem>.h5             the manifest, written by rank 0 only after every rank's part is on
!>                         disk (the CRC gather below is the barrier), also atomically: NP,
!>                         the deck's content hash, cycle, time, the parts' prefix and the
!>                         CRC-32 of each part file's bytes. A set counts as complete only
!>                         when its manifest exists, and -r names the manifest. The parts
!>                         carry the cycle, so rewriting a manifest (runrsf.h5 every CYCL
!>                         cycles) never touches the parts the old manifest names: a crash
!>                         at any moment leaves the old set or the new one whole. A rank
!>                         removes its superseded part once the new manifest is in place.
!> Continuing (`mpirun -np NP dynx -i deck.k -r <stem>.h5`): rank 0 checks the manifest (NP
!> and deck hash: input errors, exit 2, naming the file and what to do), every rank checks
!> its part's CRC against the manifest and reads it (a missing or damaged part: exit 4 naming
!> the rank and the file). Each rank gets back exactly the numbers it had, so the continued
!> run repeats the uninterrupted MPI run (itself the serial run) bit for bit.
!> A serial dump continued on NP ranks: every rank reads it into the global model of the
!> engine (serial numbering) and copies its own nodes and elements into its sub-model. The
!> reverse (an MPI dump continued serially) is refused with exit 2 naming the NP to use.
!> Plot output: a dump records the states in the rank's plot part (dx_checkpoint); the
!> continue cuts every part back to them (par_plot_resume) or, from a serial dump, fills new
!> parts from the serial d3plot.h5 (par_plot_from_serial), before rank 0 rewrites d3plot.h5.
!> Contact: the rank's contact state lives in the engine's global model (dx_par_contact:
!> replicated per-node state, the rank's own strip and candidate lists), so it is swapped
!> into the rank's model around the serial writer and reader (swap_contact): each part holds
!> its rank's contact state. Rigid bodies are model%rigid on every rank (in every part).
!> CRC-32: dx_restart_file (Sarwate 1988). Atomic replace: POSIX rename(2).
module dx_par_restart
   use, intrinsic :: iso_fortran_env, only: int8, int64
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error, EXIT_INPUT, EXIT_IO
   use dx_strings, only: str, string_t
   use dx_model, only: model_t, family_t, element_family, MAX_ES, ES_HGS, ES_DUMP
   use dx_element_types, only: ES_THK
   use dx_contact_types, only: contact_set_t
   use dx_contact_strips, only: contact_strips
   use dx_restart, only: restart_write, restart_read
   use dx_restart_file, only: rs_file_t, rs_create, rs_commit, rs_open, rs_close, crc32_bytes
   use dx_h5, only: h5_write_attr, h5_read_attr
   use dx_par, only: par_rank, par_size, par_abort, par_allreduce, PAR_MAX
   use dx_par_plan, only: par_gather_ordered
   use dx_par_agree, only: par_agree
   use dx_par_engine, only: par_engine_t, par_engine_maps
   use dx_par_plot, only: par_plot_t, par_plot_resume, par_plot_from_serial
   use dx_rank_file, only: deck_content_hash
   implicit none
   private
   public :: par_restart_write, par_restart_read, par_restart_part_name, par_restart_precheck, &
             serial_restart_read, par_restart_parts_t

   !> Parts this rank wrote or read, by manifest (removed when a new set replaces them).
   type :: part_rec_t
      character(:), allocatable :: manifest, part
   end type part_rec_t
   !> The dump parts of a rank's domain (a component of mpi_domain_t).
   type :: par_restart_parts_t
      type(part_rec_t), allocatable :: known(:)
   end type par_restart_parts_t

contains

   !> The parts' prefix of the dump set at cycle whose manifest is path: the manifest's
   !> name without .h5, then .cycC (the manifest records it without the directory).
   function part_prefix(path, cycle) result(p)
      character(*), intent(in) :: path
      integer, intent(in) :: cycle
      character(:), allocatable :: p
      integer :: n
      n = len(path)
      if (n > 3) then
         if (path(n - 2:n) == '.h5') n = n - 3
      end if
      p = path(1:n)//'.cyc'//str(cycle)
   end function part_prefix

   !> The part file of rank r: prefix.rankRRRRR.h5.
   function par_restart_part_name(prefix, r) result(p)
      character(*), intent(in) :: prefix
      integer, intent(in) :: r
      character(:), allocatable :: p
      character(5) :: num
      write(num, '(i5.5)') r
      p = prefix//'.rank'//num//'.h5'
   end function par_restart_part_name

   !> The directory of path with a trailing '/', or ''.
   function dir_of(path) result(d)
      character(*), intent(in) :: path
      character(:), allocatable :: d
      d = path(1:index(path, '/', back=.true.))
   end function dir_of

   !> Remember that part belongs to manifest; return the part it replaces ('' if none).
   subroutine remember(parts, manifest, part, old)
      type(par_restart_parts_t), intent(inout) :: parts
      character(*), intent(in) :: manifest, part
      character(:), allocatable, intent(out) :: old
      integer :: k
      old = ''
      if (.not. allocated(parts%known)) allocate(parts%known(0))
      do k = 1, size(parts%known)
         if (parts%known(k)%manifest == manifest) then
            old = parts%known(k)%part
            parts%known(k)%part = part
            return
         end if
      end do
      parts%known = [parts%known, part_rec_t(manifest, part)]
   end subroutine remember

   !> Remove a file if it exists (superseded parts; failures do not matter).
   subroutine remove_file(path)
      character(*), intent(in) :: path
      integer :: u, ios
      open(newunit=u, file=path, status='old', iostat=ios)
      if (ios == 0) close(u, status='delete', iostat=ios)
   end subroutine remove_file

   !> Collective: every rank writes its part, then rank 0 the manifest path. On failure
   !> every rank returns an error (the failing rank's own message on that rank).
   subroutine par_restart_write(eng, parts, model, path, kind, error)
      type(par_engine_t), intent(inout) :: eng
      type(par_restart_parts_t), intent(inout) :: parts
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path, kind
      type(error_t), allocatable, intent(out) :: error
      type(error_t), allocatable :: e
      type(model_t), pointer :: gp
      integer, allocatable :: ng(:), keys(:)
      real(wp), allocatable :: vals(:, :), allv(:, :)
      character(16) :: hash
      character(:), allocatable :: part, prefix, old
      integer(int64) :: crc
      integer :: me, np, code, k
      type(rs_file_t) :: rs
      me = par_rank()
      np = par_size()
      prefix = part_prefix(path, model%cycle)
      part = par_restart_part_name(prefix, me)
      call par_engine_maps(eng, gp, ng, hash)
      call swap_contact(model, gp)          ! the rank's contact state is in g (below)
      if (allocated(model%walls) .and. allocated(gp%walls)) then
         do k = 1, size(model%walls)       ! the serial wall forces (par_engine's flush)
            model%walls(k)%force = gp%walls(k)%force
         end do
      end if
      call restart_write(model, part, kind, e)
      call swap_contact(model, gp)
      crc = -1
      if (.not. allocated(e)) call file_crc(part, crc, e)
      code = 0
      if (allocated(e)) code = e%code
      allocate(vals(1, 1))
      vals(1, 1) = real(crc, wp)
      call par_gather_ordered([me], vals, keys, allv)     ! every part is on disk after this
      call par_allreduce(code, PAR_MAX)
      if (code /= 0) then
         if (allocated(e)) then
            call set_error(error, 'rank '//str(me)//': '//e%message, e%code)
         else
            call set_error(error, 'restart dump '//path//': another rank could not write '// &
                           'its part (its message names it)', code)
         end if
         return
      end if
      if (me == 0) then
         call rs_create(rs, path, 'dynx (MPI manifest)')
         call rs%put('mpi_np', np)
         call rs%put('part_crc32', allv(1, :))
         call rs%put('cycle', model%cycle)
         call rs%put('time', model%time)
         if (rs%ok()) call h5_write_attr(rs%h5, '/', 'deck_hash', hash, rs%err)
         if (rs%ok()) call h5_write_attr(rs%h5, '/', 'part_prefix', &
                                         prefix(len(dir_of(prefix)) + 1:), rs%err)
         if (rs%ok()) call h5_write_attr(rs%h5, '/', 'parts', &
            'the part of rank R is <part_prefix>.rankRRRRR.h5 in this directory', rs%err)
         call rs_commit(rs, e)
         code = 0
         if (allocated(e)) code = e%code
      end if
      call par_allreduce(code, PAR_MAX)
      if (code /= 0) then
         if (allocated(e)) then
            call move_alloc(e, error)
         else
            call set_error(error, 'restart dump '//path//': rank 0 could not write the '// &
                           'manifest (its message names it)', code)
         end if
         return
      end if
      call remember(parts, path, part, old)           ! the new set is whole: drop the old part
      if (len(old) > 0 .and. old /= part) call remove_file(old)
   end subroutine par_restart_write

   !> A serial run: restore model from the serial dump path (an MPI manifest is refused).
   subroutine serial_restart_read(model, path, error)
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      integer :: mode, mnp
      real(wp), allocatable :: crcs(:)
      character(:), allocatable :: mhash, prefix
      call inspect(path, mode, mnp, mhash, crcs, error, prefix)
      if (allocated(error)) return
      if (mode == 1) then
         call set_error(error, 'restart file '//path//' is the manifest of a dump written '// &
            'by an MPI run on '//str(mnp)//' ranks; continue it with the same number of '// &
            'ranks: mpirun -np '//str(mnp)//' dynx -i '//model%deck_file//' -r '//path, &
            EXIT_INPUT)
         return
      end if
      call restart_read(model, path, error)
   end subroutine serial_restart_read

   !> An MPI run: restore model from the dump path, a manifest and this rank's part, or a
   !> serial dump through the global model; the plot part (plot) continues. Errors that
   !> concern one rank stop every rank (par_abort) naming it.
   subroutine par_restart_read(eng, plot, parts, model, path, error)
      type(par_engine_t), intent(inout) :: eng
      type(par_restart_parts_t), intent(inout) :: parts
      type(par_plot_t), intent(inout) :: plot
      type(model_t), intent(inout) :: model
      character(*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: error
      type(model_t), pointer :: gp
      integer, allocatable :: ng(:)
      character(16) :: hash
      integer :: np, me, mode, mnp
      real(wp), allocatable :: crcs(:)
      character(:), allocatable :: mhash, part, prefix, old, msg
      integer :: code
      np = par_size()
      me = par_rank()
      call par_engine_maps(eng, gp, ng, hash)
      ! rank 0 judges the dump set; its errors stop every rank
      mode = 0
      ! (errors: every rank reaches each par_agree, and all stop together: dx_par_agree)
      if (me == 0) then
         call inspect(path, mode, mnp, mhash, crcs, error, prefix)
         if (.not. allocated(error) .and. mode == 1) then
            if (mnp /= np) then
               call set_error(error, 'restart file '//path//' is a dump of a run on '// &
                  str(mnp)//' ranks; this run has '//str(np)//'. Continue it with mpirun -np '// &
                  str(mnp)//' (a dump set continues on the number of ranks that wrote it)', &
                  EXIT_INPUT)
            else if (mhash /= hash) then
               call set_error(error, 'restart file '//path//' is a dump of another '// &
                  'deck (deck hash '//mhash//'; '//model%deck_file//' has '//hash//'). Give '// &
                  'the deck the run was started with (a restart deck, -R, may change end '// &
                  'time and output)', EXIT_INPUT)
            end if
         end if
      end if
      call par_agree(error)
      if (allocated(error)) return
      call par_allreduce(mode, PAR_MAX)
      if (mode == 1) then
         if (me /= 0) call inspect(path, mode, mnp, mhash, crcs, error, prefix)
         call par_agree(error)
         if (allocated(error)) return
         part = par_restart_part_name(dir_of(path)//prefix, me)
         call remember(parts, path, part, old)
         call check_part(part, crcs(me + 1), error)
         if (allocated(error)) call part_error(error)
         call par_agree(error)
         if (allocated(error)) return
         call swap_contact(model, gp)
         call restart_read(model, part, error)
         call swap_contact(model, gp)
         if (allocated(error)) call part_error(error)
         call par_agree(error)
         if (allocated(error)) return
      else
         ! a serial dump: into the global model, then this rank's nodes and elements
         call global_blocks(gp, .true.)      ! g's element state is freed after setup
         if (.not. allocated(gp%x)) then     ! (ranks > 0 of a root-only deck hold none)
            allocate(gp%x(3, gp%nn), gp%v(3, gp%nn), gp%f(3, gp%nn))
            gp%x = gp%x0
            gp%v = gp%v0
            gp%f = 0.0_wp
         end if
         call restart_read(gp, path, error)
         call par_agree(error)
         if (allocated(error)) return
         call scatter_global(gp, ng, model)
         call global_blocks(gp, .false.)
         if (allocated(gp%contact)) call contact_strips_all(gp%contact, gp%x)
      end if
      ! plot states: each rank continues its part file (the dump's state count; a serial
      ! dump: the parts are filled from the serial d3plot.h5 first), before rank 0 replaces
      ! d3plot.h5 (out%resume in dynx.f90, after the barrier below)
      if (mode == 1) then
         call par_plot_resume(plot, model%run%nplot, error)
      else
         call par_plot_from_serial(plot, model%run%nplot, error)
      end if
      if (allocated(error)) then
         msg = 'restart from '//path//', plot part of rank '//str(me)//': '//error%message
         code = error%code
         deallocate(error)
         call set_error(error, msg, code)
      end if
      call par_agree(error)
      if (allocated(error)) return
      gp%run = model%run            ! rank 0 resumes the output from the global model
      gp%run%nplot = 0              ! MPI: d3plot.h5 is mesh-only until the combine
      gp%time = model%time
      gp%cycle = model%cycle
      gp%dt = model%dt
      gp%dt_elem = model%dt_elem
      gp%energy = model%energy
      mode = 0
      call par_allreduce(mode, PAR_MAX)   ! every rank has its state
   contains
      !> The error of this rank's dump part, naming the dump, the rank and the part.
      subroutine part_error(error)
         type(error_t), allocatable, intent(inout) :: error
         msg = 'restart dump '//path//', part of rank '//str(me)//': '//error%message
         code = error%code
         deallocate(error)
         call set_error(error, msg, code)
      end subroutine part_error
   end subroutine par_restart_read

   !> Before the rank files are read (dynx.f90): a dump set of another number of ranks or
   !> of another deck is an input error naming the dump (not the rank files, which would
   !> mismatch too). Rank 0 looks; a serial run needs nothing here (par_restart_read
   !> refuses a manifest).
   subroutine par_restart_precheck(path, deck, error, files)
      character(*), intent(in) :: path, deck
      type(error_t), allocatable, intent(out) :: error
      !> the files the deck read (model%deck_files): hashed as they are, not by parsing the
      !> deck again (which would refuse a deck run with --ignore-unknown)
      type(string_t), intent(in) :: files(:)
      integer :: np
      np = par_size()
      if (np <= 1) return
      if (par_rank() == 0) call look(error)
      call par_agree(error)      ! rank 0's verdict stops every rank together (dx_par_agree)
   contains
      subroutine look(error)
         type(error_t), allocatable, intent(out) :: error
         integer :: mode, mnp
         character(:), allocatable :: mhash
         character(16) :: hash
         real(wp), allocatable :: crcs(:)
         call inspect(path, mode, mnp, mhash, crcs, error)
         if (allocated(error)) return
         if (mode /= 1) return
         if (mnp /= np) then
            call set_error(error, 'restart file '//path//' is a dump of '// &
               'a run on '//str(mnp)//' ranks; this run has '//str(np)//'. Continue it with '// &
               'mpirun -np '//str(mnp)//' (a dump set continues on the number of ranks that '// &
               'wrote it)', EXIT_INPUT)
            return
         end if
         call deck_content_hash(files, hash, error)
         if (allocated(error)) return
         if (mhash /= hash) call set_error(error, 'restart file '//path//' is a dump of '// &
            'another deck (deck hash '//mhash//'; '//deck//' has '//hash//'). Give the deck '// &
            'the run was started with (a restart deck, -R, may change the end time and the '// &
            'output)', EXIT_INPUT)
      end subroutine look
   end subroutine par_restart_precheck

   !> What path is: mode 1 an MPI manifest (with its NP, deck hash and part CRCs), 0 else.
   subroutine inspect(path, mode, mnp, mhash, crcs, error, prefix)
      character(*), intent(in) :: path
      integer, intent(out) :: mode, mnp
      character(:), allocatable, intent(out) :: mhash
      real(wp), allocatable, intent(out) :: crcs(:)
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable, intent(out), optional :: prefix
      type(rs_file_t) :: rs
      type(error_t), allocatable :: e
      character(:), allocatable :: pre
      mode = 0; mnp = 0; mhash = ''; pre = ''
      allocate(crcs(0))
      call rs_open(rs, path, error)
      if (allocated(error)) return
      if (rs%has('mpi_np')) then
         mode = 1
         call rs%get('mpi_np', mnp)
         if (rs%ok() .and. (mnp < 1 .or. mnp > 1000000)) call set_error(rs%err, &
            'restart file '//path//': manifest names '//str(mnp)//' ranks (damaged)', EXIT_IO)
         if (rs%ok()) then
            deallocate(crcs)
            allocate(crcs(mnp))
            call rs%get('part_crc32', crcs)
         end if
         if (rs%ok()) call h5_read_attr(rs%h5, '/', 'deck_hash', mhash, rs%err)
         if (rs%ok()) call h5_read_attr(rs%h5, '/', 'part_prefix', pre, rs%err)
      end if
      if (present(prefix)) prefix = pre
      call rs_close(rs, e)
      if (allocated(e)) call move_alloc(e, error)
   end subroutine inspect

   !> The part exists and its bytes have the CRC the manifest recorded (exit 4 otherwise).
   subroutine check_part(part, want, error)
      character(*), intent(in) :: part
      real(wp), intent(in) :: want
      type(error_t), allocatable, intent(out) :: error
      logical :: there
      integer(int64) :: crc
      inquire(file=part, exist=there)
      if (.not. there) then
         call set_error(error, part//' is missing (the dump set is incomplete; continue '// &
                        'from an earlier dump)', EXIT_IO)
         return
      end if
      call file_crc(part, crc, error)
      if (allocated(error)) return
      if (real(crc, wp) /= want) call set_error(error, part//': its CRC-32 '//str(int(crc))// &
         ' is not the '//str(int(want, int64))//' of the manifest (the part is damaged or '// &
         'belongs to another dump; continue from an earlier dump)', EXIT_IO)
   end subroutine check_part

   !> CRC-32 of a file's bytes.
   subroutine file_crc(path, crc, error)
      character(*), intent(in) :: path
      integer(int64), intent(out) :: crc
      type(error_t), allocatable, intent(out) :: error
      integer(int8), allocatable :: bytes(:)
      integer :: u, ios
      integer(int64) :: n
      crc = -1
      open(newunit=u, file=path, access='stream', form='unformatted', action='read', &
           status='old', iostat=ios)
      if (ios /= 0) then
         call set_error(error, 'cannot open '//path//' to check it', EXIT_IO); return
      end if
      inquire(unit=u, size=n)
      allocate(bytes(max(n, 0_int64)))
      if (n > 0) read(u, iostat=ios) bytes
      close(u)
      if (ios /= 0 .or. n < 0) then
         call set_error(error, 'cannot read '//path//' to check it', EXIT_IO); return
      end if
      crc = crc32_bytes(bytes)
   end subroutine file_crc

   !> Contact in an MPI run: the rank's contact state (the replicated per-node state and
   !> this rank's strips and candidate lists, dx_par_contact) is g%contact, and model%contact
   !> an empty marker. Exchanged around restart_write/restart_read (move_alloc, no copy) so
   !> that the serial writer dumps and restores the rank's own contact state in its part.
   subroutine swap_contact(model, gp)
      type(model_t), intent(inout) :: model, gp
      type(contact_set_t), allocatable :: tmp
      if (.not. allocated(model%contact) .or. .not. allocated(gp%contact)) return
      call move_alloc(model%contact, tmp)
      call move_alloc(gp%contact, model%contact)
      call move_alloc(tmp, gp%contact)
   end subroutine swap_contact

   !> A serial dump of a contact deck: its candidate lists cover every slave node, so the
   !> rank takes the strips of the current coordinates without a new sort (a strip only
   !> says which rank computes a node; every node's candidates are the serial ones), and
   !> the next sort falls on the serial run's cycle.
   subroutine contact_strips_all(cs, x)
      type(contact_set_t), intent(inout) :: cs
      real(wp), intent(in) :: x(:, :)
      integer :: i, j
      do i = 1, size(cs%iface)
         do j = 1, size(cs%iface(i)%pass)
            call contact_strips(cs%iface(i)%pass(j), x, cs%nstrip, cs%istrip, cs%mine_node)
         end do
      end do
   end subroutine contact_strips_all

   !> The element state arrays of the global model (freed after setup, dx_par_engine) for
   !> restoring a serial dump into it (on = .true.), and freed again afterwards.
   subroutine global_blocks(gp, on)
      type(model_t), intent(inout) :: gp
      logical, intent(in) :: on
      integer :: b
      type(family_t) :: fam
      do b = 1, size(gp%blocks)
         associate (blk => gp%blocks(b))
            if (on) then
               if (.not. allocated(blk%sig)) allocate(blk%sig(blk%nel, 6, blk%nip), &
                                                      source=0.0_wp)
               if (.not. allocated(blk%hv)) allocate(blk%hv(blk%nel, blk%nhv, blk%nip), &
                                                     source=0.0_wp)
               fam = element_family(blk%etype)
               if (fam%es_ncol(ES_HGS) > 0 .and. gp%parts(blk%ipart)%qh > 0.0_wp) &
                  call blk%es_add(ES_HGS, fam%es_ncol(ES_HGS))
               ! shells: thickness and hourglass forces (the ranks other than 0 freed g's
               ! family state after set-up)
               if (fam%es_ncol(ES_THK) > 0) call blk%es_add(ES_THK, fam%es_ncol(ES_THK))
            else
               if (allocated(blk%sig)) deallocate(blk%sig)
               if (allocated(blk%hv)) deallocate(blk%hv)
               call blk%es_drop(ES_HGS)
               if (par_rank() > 0) call blk%es_drop(ES_THK)
            end if
         end associate
      end do
   end subroutine global_blocks

   !> A serial dump restored into the global model gp: copy this rank's nodes (local i is
   !> global ng(i), slot nodes included) and elements (blocks hold global element numbers)
   !> and the loop state into the rank's sub-model.
   subroutine scatter_global(gp, ng, model)
      type(model_t), intent(in) :: gp
      integer, intent(in) :: ng(:)
      type(model_t), intent(inout) :: model
      integer :: b, j, e, p, k, s
      model%x(:, 1:size(ng)) = gp%x(:, ng)
      model%v(:, 1:size(ng)) = gp%v(:, ng)
      if (allocated(model%w) .and. allocated(gp%w)) model%w(:, 1:size(ng)) = gp%w(:, ng)
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            do j = 1, blk%nel
               e = blk%elem(j)
               p = gp%elem_pos(e)
               associate (gb => gp%blocks(gp%elem_block(e)))
                  blk%sig(j, :, :) = gb%sig(p, :, :)
                  if (allocated(blk%hv)) blk%hv(j, :, :) = gb%hv(p, :, :)
                  blk%relvol(j) = gb%relvol(p)
                  blk%eint(j) = gb%eint(p)
                  blk%ehg(j) = gb%ehg(p)
                  do s = 1, MAX_ES     ! the dumped family-state slots both blocks hold
                     if (blk%esc(s) > 0 .and. gb%esc(s) > 0 .and. ES_DUMP(s)) &
                        blk%es(j, blk%esc(s):blk%esc(s) + blk%esn(s) - 1) = &
                           gb%es(p, gb%esc(s):gb%esc(s) + gb%esn(s) - 1)
                  end do
                  blk%failed(j) = gb%failed(p)
               end associate
            end do
         end associate
      end do
      if (allocated(model%walls)) then
         do k = 1, size(model%walls)
            model%walls(k)%force = gp%walls(k)%force
         end do
      end if
      if (allocated(model%rigid) .and. allocated(gp%rigid)) model%rigid = gp%rigid
      ! mass scaling: the elements' added mass (by global element; each rank uses its own)
      if (allocated(model%added_mass) .and. allocated(gp%added_mass)) &
         model%added_mass = gp%added_mass
      model%run = gp%run
      model%time = gp%time
      model%dt = gp%dt
      model%cycle = gp%cycle
      model%dt_elem = gp%dt_elem
      model%energy = gp%energy
   end subroutine scatter_global
end module dx_par_restart
