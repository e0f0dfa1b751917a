!> d3hsp in the output folder (LS-DYNA's "high speed printout": the input echo, the model
!> summary, the time step; keyword manual vol. I, *CONTROL_OUTPUT): written once at the
!> start of a run, by the serial run or MPI rank 0, from the global model:
!>  1. the input echo (dx_card_echo): every keyword block read, every field its reader took
!>     with its value, `default` where the field was blank or missing;
!>  2. the model summary: nodes, elements per family, parts with material, density and mass
!>     (rho V0 summed over the part's elements, as matsum's mass), the total mass, and the
!>     units hint (dx_units_hint: the common LS-DYNA unit sets the materials fit);
!>  3. the smallest element time steps at t = 0 with their element ids, solid and 2D
!>     families: TSSFAC L/c with L the family's time-step length (elem_length: V/A_max for
!>     the hexahedron) and c the material's wave speed at V/V0 = 1 (the solver's own step
!>     adds the bulk viscosity once the elements move; shells and beams are not listed:
!>     their step is the first status line's);
!>  4. memory: the peak resident size so far.
!> No paper beyond the LS-DYNA manual's description of d3hsp; the layout is dynx's own.
module dx_d3hsp
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_strings, only: str, rstr
   use dx_model, only: model_t, family_t, element_family, elem_length
   use dx_matsum, only: part_masses
   use dx_timer, only: peak_memory_kb
   use dx_io_sys, only: sys_write_file
   use dx_units_hint, only: units_hint
   implicit none
   private
   public :: write_d3hsp

   integer, parameter :: NSMALL = 10    !< element time steps listed

contains

   !> Write OUTDIR/d3hsp: the deck's path, the echo text and model's summary.
   subroutine write_d3hsp(path, deck, echo, model, error)
      character(*), intent(in) :: path, deck, echo
      type(model_t), intent(in) :: model
      type(error_t), allocatable, intent(out) :: error
      character(:), allocatable :: t
      character, parameter :: nl = new_line('a')
      t = 'dynx d3hsp: input echo and model summary of '//deck//nl// &
          '(each field as the reader took it; "default": blank or missing in the deck, the '// &
          'reader''s default used)'//nl//nl//'==== 1. input echo'//nl//echo
      call summary(t, model)
      call time_steps(t, model)
      t = t//nl//'==== 4. memory'//nl//'  peak resident size so far: '// &
          str(int(peak_memory_kb()))//' KiB'//nl
      ! one write (a full disk is an I/O error naming the file, exit 4; no partial crash)
      call sys_write_file(path, t, error)
   end subroutine write_d3hsp

   !> Append line and a new line to t.
   subroutine put(t, line)
      character(:), allocatable, intent(inout) :: t
      character(*), intent(in) :: line
      t = t//line//new_line('a')
   end subroutine put

   subroutine summary(txt, model)
      character(:), allocatable, intent(inout) :: txt
      type(model_t), intent(in) :: model
      real(wp), allocatable :: pm(:)
      character(:), allocatable :: names(:)
      integer, allocatable :: cnt(:)
      type(family_t) :: f
      integer :: b, k, n, p
      character(160) :: line
      call put(txt, '')
      call put(txt, '==== 2. model summary')
      call put(txt, '  nodes          '//str(model%nn))
      call put(txt, '  elements       '//str(model%ne))
      allocate(character(8) :: names(size(model%blocks)))
      allocate(cnt(size(model%blocks)))
      n = 0
      do b = 1, size(model%blocks)
         f = element_family(model%blocks(b)%etype)
         do k = n, 0, -1                       ! (gfortran 12's findloc on a character
            if (k == 0) exit                   ! array of size 0 reads past it)
            if (names(k) == f%name) exit
         end do
         if (k == 0) then
            n = n + 1; k = n
            names(k) = f%name; cnt(k) = 0
         end if
         cnt(k) = cnt(k) + model%blocks(b)%nel
      end do
      do k = 1, n
         call put(txt, '    family '//names(k)//' '//str(cnt(k))//' elements')
      end do
      call put(txt, '  parts          '//str(size(model%parts)))
      call put(txt, '       part   material  type     density         mass')
      pm = part_masses(model)
      do p = 1, size(model%parts)
         associate (pt => model%parts(p))
            line = ''
            if (pt%imat > 0) then
               write(line, '(3i10,es12.4)') pt%label, pt%mid, model%mats(pt%imat)%m%mtype, &
                  model%mats(pt%imat)%m%ro
            else
               write(line, '(2i10)') pt%label, pt%mid
            end if
            if (allocated(pm)) write(line(43:), '(es13.5)') pm(p)
            call put(txt, trim(line))
         end associate
      end do
      if (allocated(pm)) call put(txt, '  total mass     '//rstr(sum(pm)))
      call hint(txt, model)
   end subroutine summary

   !> The units hint (dx_units_hint) from each solid or 2D material's density and wave speed
   !> at t = 0 (first block of a part using it, zero history as in time_steps).
   subroutine hint(txt, model)
      character(:), allocatable, intent(inout) :: txt
      type(model_t), intent(in) :: model
      real(wp), allocatable :: rho(:), cs(:), hv0(:, :)
      logical, allocatable :: seen(:)
      real(wp) :: c(1)
      integer :: b, im
      type(family_t) :: f
      allocate(rho(0), cs(0), seen(size(model%mats)))
      seen = .false.
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            f = element_family(blk%etype)
            if (f%rot .or. f%nen > 8) cycle
            im = model%parts(blk%ipart)%imat
            if (im == 0) cycle
            if (seen(im)) cycle
            seen(im) = .true.
            associate (mat => model%mats(im)%m)
               if (mat%is_rigid .or. .not. (mat%ro > 0.0_wp)) cycle
               if (allocated(hv0)) deallocate(hv0)
               allocate(hv0(1, max(1, blk%nhv)))
               hv0 = 0.0_wp
               call mat%wave_speed(1, [1.0_wp], hv0, c)
               if (.not. (c(1) > 0.0_wp)) cycle
               rho = [rho, mat%ro]
               cs = [cs, c(1)]
            end associate
         end associate
      end do
      txt = txt//units_hint(rho, cs, model%ctrl%endtim)
   end subroutine hint

   !> The NSMALL smallest TSSFAC L/c at t = 0 of the solid and 2D elements, with their ids.
   subroutine time_steps(txt, model)
      character(:), allocatable, intent(inout) :: txt
      type(model_t), intent(in) :: model
      real(wp) :: dts(NSMALL), c(1), xe(3, 8), l, dt
      real(wp), allocatable :: hv0(:, :)
      integer :: ids(NSMALL), b, e, m, k, nen
      type(family_t) :: f
      character(100) :: line
      dts = huge(1.0_wp)
      ids = 0
      do b = 1, size(model%blocks)
         associate (blk => model%blocks(b))
            f = element_family(blk%etype)
            if (f%rot .or. f%nen > 8 .or. .not. allocated(blk%vol0)) cycle
            if (model%parts(blk%ipart)%imat == 0) cycle
            associate (mat => model%mats(model%parts(blk%ipart)%imat)%m)
               if (mat%is_rigid .or. .not. (mat%ro > 0.0_wp)) cycle
               nen = f%nen
               if (allocated(hv0)) deallocate(hv0)
               allocate(hv0(1, max(1, blk%nhv)))
               hv0 = 0.0_wp
               do e = 1, blk%nel
                  if (.not. (blk%vol0(e) > 0.0_wp)) cycle
                  xe(:, 1:nen) = model%x0(:, blk%conn(1:nen, e))
                  l = elem_length(blk%etype, xe(:, 1:nen), blk%vol0(e))
                  if (allocated(blk%hv)) then
                     call mat%wave_speed(1, [1.0_wp], blk%hv(e:e, :, 1), c)
                  else        ! MPI: rank 0's global model holds no history: the state at
                     call mat%wave_speed(1, [1.0_wp], hv0, c)   ! t = 0 (zero)
                  end if
                  if (.not. (c(1) > 0.0_wp)) cycle
                  dt = model%ctrl%tssfac*l/c(1)
                  if (dt >= dts(NSMALL)) cycle
                  m = NSMALL                   ! insert, kept sorted
                  do while (m > 1)
                     if (dts(m - 1) <= dt) exit
                     dts(m) = dts(m - 1); ids(m) = ids(m - 1)
                     m = m - 1
                  end do
                  dts(m) = dt; ids(m) = model%elem_label(blk%elem(e))
               end do
            end associate
         end associate
      end do
      call put(txt, '')
      call put(txt, '==== 3. smallest element time steps at t = 0 (TSSFAC L/c; solids, 2D)')
      call put(txt, '    element     time step')
      do k = 1, NSMALL
         if (ids(k) == 0) exit
         write(line, '(i11,es14.5)') ids(k), dts(k)
         call put(txt, trim(line))
      end do
   end subroutine time_steps
end module dx_d3hsp
