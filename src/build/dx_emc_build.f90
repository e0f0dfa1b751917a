!> Build the conserving rigid-body contact system (model%emc) from *CONTROL_IMPLICIT_GENERAL,
!> *DYNX_CONSERVING_CONTACT, *DYNX_RIGID_SPHERE and *DYNX_CONSERVING_CONTROL: the contact
!> definitions (rigid bodies only), the exterior facets and surface nodes of each body in its
!> principal frame, and the sphere fits (centre and radius by the algebraic least-squares fit
!> |x|^2 = 2 c.x + k of Kasa 1976, IEEE Trans. Instrum. Meas. 25:8-14; the largest radial
!> deviation |r_i - R|/R is the fit error, checked against TOL).
module dx_emc_build
   use dx_kinds, only: wp
   use dx_error, only: error_t, set_error
   use dx_strings, only: str, rstr
   use dx_log, only: log_info
   use dx_model, only: model_t, family_t, element_family, MAX_FACES
   use dx_model_input, only: model_input_t
   use dx_contact_build, only: face_key
   use dx_dense_solve, only: dense_solve
   use dx_emc_types, only: emc_system_t, emc_facet_t, emc_sphere_in_t
   implicit none
   private
   public :: build_emc, fit_sphere

contains

   function at(inp, ifile, line, key) result(s)
      type(model_input_t), intent(in) :: inp
      integer, intent(in) :: ifile, line
      character(*), intent(in) :: key
      character(:), allocatable :: s
      s = inp%files(ifile)%s//':'//str(line)//': *'//key//': '
   end function at

   !> the rigid body of part label pid (0: none); msg says why not
   subroutine find_body(model, pid, b, msg)
      type(model_t), intent(in) :: model
      integer, intent(in) :: pid
      integer, intent(out) :: b
      character(:), allocatable, intent(out) :: msg
      integer :: i
      b = 0
      msg = ''
      if (allocated(model%rigid)) then
         do i = 1, size(model%rigid%bodies)
            if (model%rigid%bodies(i)%label == pid .and. &
                model%rigid%bodies(i)%ipart > 0) b = i
         end do
      end if
      if (b > 0) return
      do i = 1, size(model%parts)
         if (model%parts(i)%label == pid) then
            msg = 'part '//str(pid)//' is not a rigid part (*MAT_RIGID): conserving contact '// &
                  'is defined between rigid bodies only'
            return
         end if
      end do
      msg = 'part '//str(pid)//' is not defined (*PART)'
   end subroutine find_body

   !> Build model%emc when the deck asks for conserving contact; nothing otherwise.
   subroutine build_emc(inp, model, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(inout) :: model
      type(error_t), allocatable, intent(out) :: error
      integer :: nc, i, b, e, k, nd, ibad
      character(:), allocatable :: msg, key
      nc = 0
      if (allocated(inp%emc%contacts)) nc = size(inp%emc%contacts)
      if (nc == 0) then
         ! (IMFLAG = 1 without it: the implicit Newton solver, dx_implicit)
         if (allocated(inp%emc%spheres)) then
            if (size(inp%emc%spheres) > 0) call set_error(error, at(inp, &
               inp%emc%spheres(1)%ifile, inp%emc%spheres(1)%line, 'DYNX_RIGID_SPHERE')// &
               'a spherical part is used only by *DYNX_CONSERVING_CONTACT, which the deck lacks')
         end if
         return
      end if
      key = 'DYNX_CONSERVING_CONTACT'
      associate (c1 => inp%emc%contacts(1))
         if (inp%ctrl%imp%imflag /= 1) then
            call set_error(error, at(inp, c1%ifile, c1%line, key)//'needs the implicit '// &
               'solver: *CONTROL_IMPLICIT_GENERAL with IMFLAG = 1 and DT0 > 0')
            return
         end if
         if (.not. (model%ctrl%endtim > 0.0_wp)) then
            call set_error(error, at(inp, c1%ifile, c1%line, key)//'needs an end time '// &
                           '(*CONTROL_TERMINATION ENDTIM > 0)')
            return
         end if
      end associate
      allocate(model%emc)
      associate (es => model%emc)
         es%maxit = inp%emc%maxit
         es%rtol = inp%emc%rtol
         associate (rho_inf => inp%ctrl%imp%rho_inf)   ! the step DT0: model%ctrl%imp
            es%chi = (1.0_wp - rho_inf)/(2.0_wp*(1.0_wp + rho_inf))
         end associate
         es%nfail = inp%emc%nfail
         es%out_dt = inp%emc%out_dt
         allocate(es%defs(nc))
         do i = 1, nc
            associate (c => inp%emc%contacts(i))
               call find_body(model, c%spid, es%defs(i)%sb, msg)
               if (len(msg) > 0) then
                  call set_error(error, at(inp, c%ifile, c%line, key)//'field SPID: '//msg)
                  return
               end if
               call find_body(model, c%mpid, es%defs(i)%mb, msg)
               if (len(msg) > 0) then
                  call set_error(error, at(inp, c%ifile, c%line, key)//'field MPID: '//msg)
                  return
               end if
               es%defs(i)%cid = c%cid
               es%defs(i)%eps = c%eps
               es%defs(i)%form = c%form
               es%defs(i)%fs = c%fs
               es%defs(i)%dfric = c%dfric
            end associate
         end do
         ! the conserving solver advances free rigid bodies only
         do e = 1, model%ne
            associate (blk => model%blocks(model%elem_block(e)))
               do k = 1, size(blk%conn, 1)
                  nd = blk%conn(k, model%elem_pos(e))
                  if (model%rigid%node_body(nd) == 0) then
                     call set_error(error, at(inp, inp%emc%contacts(1)%ifile, &
                        inp%emc%contacts(1)%line, key)//'part '// &
                        str(model%parts(model%elem_part(e))%label)//' is not rigid: the '// &
                        'conserving solver (IMFLAG = 1) runs decks of rigid parts only')
                     return
                  end if
               end do
            end associate
         end do
         do b = 1, size(model%rigid%bodies)
            associate (bd => model%rigid%bodies(b))
               if (any(bd%fix_t) .or. any(bd%fix_r) .or. allocated(bd%motions)) then
                  if (allocated(bd%motions)) then
                     if (size(bd%motions) == 0 .and. .not. (any(bd%fix_t) .or. &
                         any(bd%fix_r))) cycle
                  end if
                  call set_error(error, at(inp, inp%emc%contacts(1)%ifile, &
                     inp%emc%contacts(1)%line, key)//'rigid body '//str(bd%label)// &
                     ' is constrained (CON1/CON2 or prescribed motion): the conserving '// &
                     'solver advances free bodies only')
                  return
               end if
            end associate
         end do
         if (size(inp%body_loads) > 0) then
            call set_error(error, at(inp, inp%emc%contacts(1)%ifile, &
               inp%emc%contacts(1)%line, key)//'body loads (*LOAD_BODY) are not supported '// &
               'by the conserving solver (it conserves the energy of free systems)')
            return
         end if
         call build_surfaces(model, es, ibad)
         if (ibad > 0) then
            call set_error(error, at(inp, inp%emc%contacts(1)%ifile, &
               inp%emc%contacts(1)%line, key)//'a rigid body has a degenerate (zero-area) '// &
               'exterior face with node '//str(model%node_label(ibad))//': check the *NODE '// &
               'coordinates of its elements')
            return
         end if
         allocate(es%sphere(size(model%rigid%bodies)))
         if (allocated(inp%emc%spheres)) then
            do i = 1, size(inp%emc%spheres)
               call build_sphere(inp, model, es, inp%emc%spheres(i), error)
               if (allocated(error)) return
            end do
         end if
         do i = 1, nc
            associate (d => es%defs(i), c => inp%emc%contacts(i))
               if (es%sphere(d%sb)%r > 0.0_wp .and. es%sphere(d%sb)%side == 1) then
                  call set_error(error, at(inp, c%ifile, c%line, key)//'field SPID: the '// &
                     'slave is a spherical shell (SIDE = 1): make the shell the master')
                  return
               end if
               if (es%sphere(d%sb)%r == 0.0_wp .and. es%sn_ptr(d%sb + 1) == es%sn_ptr(d%sb)) &
                  then
                  call set_error(error, at(inp, c%ifile, c%line, key)//'field SPID: part '// &
                     str(c%spid)//' has no surface nodes')
                  return
               end if
               if (es%sphere(d%mb)%r == 0.0_wp .and. &
                   es%fac_ptr(d%mb + 1) == es%fac_ptr(d%mb)) then
                  call set_error(error, at(inp, c%ifile, c%line, key)//'field MPID: part '// &
                     str(c%mpid)//' has no exterior faces')
                  return
               end if
            end associate
         end do
         call log_info('emc: '//str(nc)//' conserving contact(s), '// &
            str(size(es%facets))//' facets, '//str(size(es%snodes, 2))//' surface nodes')
      end associate
   end subroutine build_emc

   !> Exterior faces (used by one element of the body's part) and their nodes, body frame.
   subroutine build_surfaces(model, es, ibad)
      type(model_t), intent(in) :: model
      type(emc_system_t), intent(inout) :: es
      integer :: nb, b, e, k, nf, i, j, m, np, nd(4), key(4), cnt
      type(family_t) :: fam
      integer, allocatable :: fk(:, :), fn(:, :), fe(:), mark(:)
      type(emc_facet_t), allocatable :: fac(:)
      real(wp), allocatable :: sn(:, :)
      integer, allocatable :: snn(:)
      integer, intent(out) :: ibad   !< a node of a zero-area face (0: none)
      real(wp) :: xe(3), nrm(3)
      logical :: shared
      ibad = 0
      nb = size(model%rigid%bodies)
      allocate(es%fac_ptr(nb + 1), es%sn_ptr(nb + 1), fac(0), sn(3, 0), snn(0))
      allocate(mark(model%nn))
      es%fac_ptr(1) = 1
      es%sn_ptr(1) = 1
      do b = 1, nb
         associate (bd => model%rigid%bodies(b))
            nf = 0
            allocate(fk(4, MAX_FACES*model%ne), fn(4, MAX_FACES*model%ne), &
                     fe(MAX_FACES*model%ne))
            do e = 1, model%ne
               if (model%elem_part(e) /= bd%ipart) cycle
               fam = element_family(model%blocks(model%elem_block(e))%etype)
               do k = 1, fam%nfaces
                  nd = model%blocks(model%elem_block(e))%conn(fam%faces(:, k), model%elem_pos(e))
                  nf = nf + 1
                  fn(:, nf) = nd
                  fk(:, nf) = face_key(nd)
                  fe(nf) = e
               end do
            end do
            mark = 0
            do i = 1, nf
               shared = .false.
               do j = 1, nf
                  if (j /= i .and. all(fk(:, j) == fk(:, i))) then
                     shared = .true.; exit
                  end if
               end do
               if (shared) cycle
               key = fn(:, i)
               np = 0
               nd = 0
               do m = 1, 4
                  if (any(nd(1:np) == key(m))) cycle
                  np = np + 1; nd(np) = key(m)
               end do
               if (np < 3) cycle
               block
                  type(emc_facet_t) :: f
                  real(wp) :: xs(3, 4)
                  do m = 1, np
                     xs(:, m) = matmul(transpose(bd%rot), model%x0(:, nd(m)) - bd%xc)
                     mark(nd(m)) = 1
                  end do
                  f%np = np
                  f%p(:, 1:np) = xs(:, 1:np)
                  f%c = sum(xs(:, 1:np), dim=2)/np
                  f%rad = 0.0_wp
                  do m = 1, np
                     f%rad = max(f%rad, norm2(xs(:, m) - f%c))
                  end do
                  if (np == 4) then
                     nrm = cross(xs(:, 3) - xs(:, 1), xs(:, 4) - xs(:, 2))
                  else
                     nrm = cross(xs(:, 2) - xs(:, 1), xs(:, 3) - xs(:, 1))
                  end if
                  if (.not. (norm2(nrm) > 0.0_wp)) then
                     if (ibad == 0) ibad = nd(1)
                     cycle
                  end if
                  nrm = nrm/norm2(nrm)
                  xe = 0.0_wp
                  do m = 1, 8
                     xe = xe + model%x0(:, model%blocks(model%elem_block(fe(i)))%conn(m, &
                          model%elem_pos(fe(i))))/8.0_wp
                  end do
                  xe = matmul(transpose(bd%rot), xe - bd%xc)
                  if (dot_product(nrm, f%c - xe) < 0.0_wp) then
                     nrm = -nrm
                     f%p(:, 1:np) = f%p(:, np:1:-1)
                  end if
                  f%n = nrm
                  fac = [fac, f]
               end block
            end do
            deallocate(fk, fn, fe)
            cnt = 0
            do i = 1, size(bd%nodes)
               if (mark(bd%nodes(i)) == 1) then
                  sn = reshape([sn, bd%s(:, i)], [3, size(sn, 2) + 1])
                  snn = [snn, bd%nodes(i)]
                  cnt = cnt + 1
               end if
            end do
            es%fac_ptr(b + 1) = size(fac) + 1
            es%sn_ptr(b + 1) = es%sn_ptr(b) + cnt
         end associate
      end do
      call move_alloc(fac, es%facets)
      call move_alloc(sn, es%snodes)
      call move_alloc(snn, es%sn_node)
   end subroutine build_surfaces

   !> Cross product, kept local: inlined here it keeps the rounding that the conservation
   !> checks of the conserving solver were measured with (dx_vec3's is called out of line).
   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

   !> Least-squares sphere through points x(3, n): centre c, radius r, max |r_i - r|/r.
   subroutine fit_sphere(x, c, r, err)
      real(wp), intent(in) :: x(:, :)
      real(wp), intent(out) :: c(3), r, err
      real(wp) :: a(4, 4), rhs(4), row(4), x0(3)
      integer :: i
      character(:), allocatable :: msg
      x0 = sum(x, dim=2)/size(x, 2)
      a = 0.0_wp
      rhs = 0.0_wp
      do i = 1, size(x, 2)
         row = [2.0_wp*(x(:, i) - x0), 1.0_wp]
         a = a + spread(row, 2, 4)*spread(row, 1, 4)
         rhs = rhs + row*sum((x(:, i) - x0)**2)
      end do
      call dense_solve(a, rhs, msg)
      if (len(msg) > 0) then
         c = x0; r = 0.0_wp; err = huge(1.0_wp); return
      end if
      c = x0 + rhs(1:3)
      r = sqrt(max(rhs(4) + sum(rhs(1:3)**2), 0.0_wp))
      err = 0.0_wp
      do i = 1, size(x, 2)
         err = max(err, abs(norm2(x(:, i) - c) - r)/max(r, tiny(1.0_wp)))
      end do
   end subroutine fit_sphere

   !> Fit the sphere of one *DYNX_RIGID_SPHERE part from its surface nodes: the outer
   !> (SIDE 0) or inner (SIDE 1) ones, split at the mean of the smallest and largest distance
   !> from their centroid.
   subroutine build_sphere(inp, model, es, s, error)
      type(model_input_t), intent(in) :: inp
      type(model_t), intent(in) :: model
      type(emc_system_t), intent(inout) :: es
      type(emc_sphere_in_t), intent(in) :: s
      type(error_t), allocatable, intent(out) :: error
      integer :: b, i, n
      real(wp) :: x0(3), d, dmin, dmax, c(3), r, err
      real(wp), allocatable :: pts(:, :)
      character(:), allocatable :: msg
      logical :: take
      call find_body(model, s%pid, b, msg)
      if (len(msg) > 0) then
         call set_error(error, at(inp, s%ifile, s%line, 'DYNX_RIGID_SPHERE')//'field PID: '//msg)
         return
      end if
      associate (sn => es%snodes(:, es%sn_ptr(b):es%sn_ptr(b + 1) - 1))
         x0 = sum(sn, dim=2)/max(size(sn, 2), 1)
         dmin = huge(1.0_wp); dmax = 0.0_wp
         do i = 1, size(sn, 2)
            d = norm2(sn(:, i) - x0)
            dmin = min(dmin, d); dmax = max(dmax, d)
         end do
         allocate(pts(3, size(sn, 2)))
         n = 0
         do i = 1, size(sn, 2)
            d = norm2(sn(:, i) - x0)
            take = d >= 0.5_wp*(dmin + dmax)
            if (s%side == 1) take = .not. take
            if (dmax - dmin <= 1.0e-6_wp*dmax) take = .true.
            if (take) then
               n = n + 1; pts(:, n) = sn(:, i)
            end if
         end do
      end associate
      if (n < 4) then
         call set_error(error, at(inp, s%ifile, s%line, 'DYNX_RIGID_SPHERE')//'field PID: '// &
            'part '//str(s%pid)//' has '//str(n)//' surface nodes on the requested side; '// &
            'a sphere fit needs at least 4')
         return
      end if
      call fit_sphere(pts(:, 1:n), c, r, err)
      call log_info('emc: part '//str(s%pid)//' spherical ('//trim(merge('outer', 'inner', &
         s%side == 0))//' surface, '//str(n)//' nodes): radius '//rstr(r)// &
         ', fit error (max |r_i - R|/R) '//rstr(err))
      if (.not. (err <= s%tol)) then
         call set_error(error, at(inp, s%ifile, s%line, 'DYNX_RIGID_SPHERE')//'field TOL: '// &
            'the surface nodes of part '//str(s%pid)//' do not lie on a sphere: fit error '// &
            rstr(err)//' (max |r_i - R|/R, R = '//rstr(r)//') > TOL = '//rstr(s%tol))
         return
      end if
      es%sphere(b)%c = c
      es%sphere(b)%r = r
      es%sphere(b)%side = s%side
      es%sphere(b)%fit_err = err
   end subroutine build_sphere
end module dx_emc_build
