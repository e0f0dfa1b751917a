!> Unit tests of the element-family seam and the tet4 family: the family table (faces
!> outward and closed, lumped shares summing to 1), the exact tetrahedron volume and moments
!> against the degenerate hexahedron of the same shape (n4 = n3, n5 = n6 = n7 = n8), the
!> constant-strain patch test of ELFORM 10 (48 tetrahedra of a distorted 2x2x2 patch under
!> a linear velocity field: stress = C:eps in every element and zero force on the interior
!> node, to round-off), a rigid translation (no strain), the time step of the unit right
!> tetrahedron (smallest altitude 1/sqrt(3) over c), the dispatch through element_block_pass,
!> and the classification of *ELEMENT_SOLID cards with repeated nodes (degenerate solids,
!> *CONTROL_SOLID ESORT).
program test_elements
   use dx_kinds, only: wp, nv_chunk
   use dx_error, only: error_t
   use dx_model, only: elem_block_t, part_t
   use dx_mat_elastic, only: mat_elastic_t
   use dx_element_types, only: family_t, element_family, elem_volume, elem_moments, &
                               elem_length, solid_shape, ETYPE_HEX8_1PT, ETYPE_TET4
   use dx_element, only: element_block_pass, block_result_t
   use dx_assert, only: check, check_close, assert_summary
   implicit none
   type(mat_elastic_t) :: mat
   type(error_t), allocatable :: err
   type(part_t) :: part
   type(elem_block_t) :: blk
   type(block_result_t) :: res
   real(wp), allocatable :: x(:, :), xm(:, :), v(:, :), f(:, :)
   real(wp) :: lg(3, 3), dt, eps(6), lam, g2, smax, w, c
   integer :: i, k

   mat%ro = 7.8e-9_wp; mat%e = 2.0e5_wp; mat%pr = 0.3_wp
   call mat%setup(err)
   call test_table(ETYPE_HEX8_1PT)
   call test_table(ETYPE_TET4)
   call test_degenerate_hex()
   call test_solid_shape()

   ! ---- patch test: v = L x at the mid-step geometry gives the strain increment sym(L) dt
   lg = reshape([1.0_wp, 0.3_wp, -0.2_wp, 0.5_wp, -0.7_wp, 0.1_wp, 0.4_wp, 0.2_wp, 0.6_wp], &
                [3, 3])*1.0e-3_wp
   dt = 1.0e-2_wp
   call make_patch()
   do i = 1, size(x, 2)
      v(:, i) = matmul(lg, xm(:, i))
      x(:, i) = xm(:, i) + 0.5_wp*dt*v(:, i)
   end do
   f = 0.0_wp
   call element_block_pass(blk, mat, part, x, v, dt, f, res)
   call check(res%ibad == 0, 'tet4 patch: no element error')
   eps = [lg(1,1), lg(2,2), lg(3,3), 0.5_wp*(lg(1,2) + lg(2,1)), 0.5_wp*(lg(2,3) + lg(3,2)), &
          0.5_wp*(lg(3,1) + lg(1,3))]*dt
   lam = mat%bulk - 2.0_wp*mat%shear/3.0_wp
   g2 = 2.0_wp*mat%shear
   smax = 0.0_wp
   do k = 1, 6
      w = g2*eps(k)
      if (k <= 3) w = w + lam*sum(eps(1:3))
      smax = max(smax, maxval(abs(blk%sig(1:blk%nel, k, 1) - w)))
   end do
   call check_close(smax, 0.0_wp, 1.0e-12_wp*g2*maxval(abs(eps)), 0.0_wp, &
                    'tet4 patch: uniform stress C:eps in all 48 elements')
   call check_close(maxval(abs(f(:, 14))), 0.0_wp, 1.0e-12_wp*maxval(abs(f)), 0.0_wp, &
                    'tet4 patch: interior node force')
   call check(res%dehg == 0.0_wp, 'tet4 patch: no hourglass energy')

   ! ---- rigid translation: no strain, no stress, no force
   call make_patch()
   v = 0.0_wp
   v(1, :) = 3.0_wp; v(2, :) = -1.0_wp
   x = xm + 0.5_wp*dt*v
   f = 0.0_wp
   call element_block_pass(blk, mat, part, x, v, dt, f, res)
   call check_close(maxval(abs(blk%sig)) + maxval(abs(f)), 0.0_wp, 1.0e-9_wp, 0.0_wp, &
                    'tet4: rigid translation gives no stress (round-off of B sums)')

   ! ---- time step of the unit right tetrahedron: L = 3V/A_max = 1/sqrt(3)
   call reset_block(1)
   if (allocated(x)) deallocate(x, xm, v, f)
   allocate(x(3, 4), xm(3, 4), v(3, 4), f(3, 4))
   x = reshape([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]*1.0_wp, [3, 4])
   v = 0.0_wp
   f = 0.0_wp
   blk%conn(:, 1) = [1, 2, 3, 4]
   blk%vol0 = 1.0_wp/6.0_wp
   call element_block_pass(blk, mat, part, x, v, 1.0e-7_wp, f, res)
   c = sqrt((mat%bulk + 4.0_wp*mat%shear/3.0_wp)/mat%ro)
   call check_close(res%dt, 1.0_wp/sqrt(3.0_wp)/c, 0.0_wp, 1.0e-14_wp, &
                    'tet4: time step = smallest altitude / c')
   call check_close(elem_length(ETYPE_TET4, x, 1.0_wp/6.0_wp), 1.0_wp/sqrt(3.0_wp), 0.0_wp, &
                    1.0e-14_wp, 'table: tet length = smallest altitude')
   call assert_summary()

contains

   !> Faces outward and closed (the area vectors sum to zero and each points away from the
   !> element's centroid) on the element's reference shape; lumped shares sum to 1.
   subroutine test_table(etype)
      integer, intent(in) :: etype
      type(family_t) :: fam
      real(wp), allocatable :: xe(:, :)
      real(wp) :: a(3), asum(3), xc(3), fc(3)
      integer :: kf
      logical :: outward
      fam = element_family(etype)
      if (fam%nen == 8) then
         xe = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1] &
                      *1.0_wp, [3, 8])
      else
         xe = reshape([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]*1.0_wp, [3, 4])
      end if
      xc = sum(xe, dim=2)/real(fam%nen, wp)
      asum = 0.0_wp
      outward = .true.
      do kf = 1, fam%nfaces
         associate (n => fam%faces(:, kf))
            a = 0.5_wp*cross3(xe(:, n(3)) - xe(:, n(1)), xe(:, n(4)) - xe(:, n(2)))
            fc = (xe(:, n(1)) + xe(:, n(2)) + xe(:, n(3)) + xe(:, n(4)))/4.0_wp
         end associate
         asum = asum + a
         if (dot_product(a, fc - xc) <= 0.0_wp) outward = .false.
      end do
      call check(outward, 'table '//trim(fam%name)//': faces outward')
      call check_close(maxval(abs(asum)), 0.0_wp, 1.0e-15_wp, 0.0_wp, &
                       'table '//trim(fam%name)//': faces closed')
      call check_close(fam%mass_share*fam%nen, 1.0_wp, 0.0_wp, 0.0_wp, &
                       'table '//trim(fam%name)//': lumped shares sum to 1')
      call check(fam%nedges == merge(12, 6, fam%nen == 8), &
                 'table '//trim(fam%name)//': edges')
   end subroutine test_table

   !> A tetrahedron and the degenerate hexahedron of the same shape (n4 = n3, n5..n8 = apex):
   !> the same exact volume and moments.
   subroutine test_degenerate_hex()
      real(wp) :: xt(3, 4), xh(3, 8), vt, vh, m1t(3), m1h(3), m2t(3, 3), m2h(3, 3), xr(3)
      xt = reshape([0.1_wp, -0.2_wp, 0.0_wp, 2.0_wp, 0.1_wp, 0.3_wp, 0.4_wp, 1.7_wp, -0.1_wp, &
                    0.5_wp, 0.6_wp, 1.9_wp], [3, 4])
      xh(:, 1:3) = xt(:, 1:3)
      xh(:, 4) = xt(:, 3)
      do i = 5, 8
         xh(:, i) = xt(:, 4)
      end do
      xr = [0.3_wp, -1.0_wp, 2.0_wp]
      vt = elem_volume(ETYPE_TET4, xt)
      vh = elem_volume(ETYPE_HEX8_1PT, xh)
      call check_close(vh, vt, 0.0_wp, 1.0e-14_wp, 'degenerate hex volume = tet volume')
      call elem_moments(ETYPE_TET4, xt, xr, vt, m1t, m2t)
      call elem_moments(ETYPE_HEX8_1PT, xh, xr, vh, m1h, m2h)
      call check_close(maxval(abs(m1h - m1t)), 0.0_wp, 1.0e-13_wp*maxval(abs(m1t)), 0.0_wp, &
                       'degenerate hex first moment = tet')
      call check_close(maxval(abs(m2h - m2t)), 0.0_wp, 1.0e-13_wp*maxval(abs(m2t)), 0.0_wp, &
                       'degenerate hex second moment = tet')
   end subroutine test_degenerate_hex

   !> *ELEMENT_SOLID cards with repeated nodes: LS-DYNA's degenerate solids and ESORT.
   subroutine test_solid_shape()
      integer :: c(8), et, nen
      logical :: ok
      c = [1, 2, 3, 4, 5, 6, 7, 8]; et = ETYPE_HEX8_1PT
      call solid_shape(0, c, et, nen, ok)
      call check(ok .and. et == ETYPE_HEX8_1PT .and. nen == 8, 'card: hexahedron')
      c = [1, 2, 3, 3, 5, 5, 5, 5]; et = ETYPE_HEX8_1PT
      call solid_shape(0, c, et, nen, ok)
      call check(ok .and. et == ETYPE_HEX8_1PT .and. nen == 8, &
                 'card: degenerate tetrahedron stays a hexahedron (ESORT 0)')
      c = [1, 2, 3, 3, 5, 5, 5, 5]; et = ETYPE_HEX8_1PT
      call solid_shape(1, c, et, nen, ok)
      call check(ok .and. et == ETYPE_TET4 .and. nen == 4 .and. all(c(1:4) == [1, 2, 3, 5]), &
                 'card: ESORT 1 sorts the degenerate tetrahedron to ELFORM 10')
      c = [1, 2, 3, 3, 5, 6, 7, 7]; et = ETYPE_HEX8_1PT
      call solid_shape(2, c, et, nen, ok)
      call check(ok .and. et == ETYPE_HEX8_1PT .and. nen == 8, &
                 'card: pentahedron stays a hexahedron (no ELFORM 15)')
      c = [1, 2, 3, 4, 5, 6, 7, 7]; et = ETYPE_HEX8_1PT
      call solid_shape(1, c, et, nen, ok)
      call check(.not. ok, 'card: other repeats are rejected')
      c = [1, 2, 3, 4, 4, 4, 4, 4]; et = ETYPE_TET4
      call solid_shape(0, c, et, nen, ok)
      call check(ok .and. nen == 4 .and. all(c(1:4) == [1, 2, 3, 4]), &
                 'card: ELFORM 10 tetrahedron N1 N2 N3 N4 N4 N4 N4 N4')
      c = [1, 2, 3, 3, 4, 4, 4, 4]; et = ETYPE_TET4
      call solid_shape(0, c, et, nen, ok)
      call check(ok .and. nen == 4 .and. all(c(1:4) == [1, 2, 3, 4]), &
                 'card: ELFORM 10 tetrahedron N1 N2 N3 N3 N4 N4 N4 N4')
      c = [1, 2, 2, 2, 2, 2, 2, 2]; et = ETYPE_TET4
      call solid_shape(0, c, et, nen, ok)
      call check(.not. ok, 'card: ELFORM 10 with 2 distinct nodes is rejected')
   end subroutine test_solid_shape

   pure function cross3(a, b) result(cc)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: cc(3)
      cc = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross3

   !> 3x3x3 nodes on [0,2]^3, the interior node 14 moved off the centre; every cell of the
   !> 2x2x2 grid split into 6 tetrahedra around its main diagonal (Kuhn), ordered to positive
   !> volume: 48 elements.
   subroutine make_patch()
      integer, parameter :: kuhn(4, 6) = reshape([1, 2, 3, 7,  1, 3, 4, 7,  1, 4, 8, 7, &
                                                  1, 8, 5, 7,  1, 5, 6, 7,  1, 6, 2, 7], [4, 6])
      integer :: ix, iy, iz, n, e, cn(8), t, tmp
      real(wp) :: vv
      if (allocated(x)) deallocate(x, xm, v, f)
      allocate(x(3, 27), xm(3, 27), v(3, 27), f(3, 27))
      n = 0
      do iz = 0, 2
         do iy = 0, 2
            do ix = 0, 2
               n = n + 1
               xm(:, n) = [real(ix, wp), real(iy, wp), real(iz, wp)]
            end do
         end do
      end do
      xm(:, 14) = [1.13_wp, 0.91_wp, 1.07_wp]
      x = xm
      call reset_block(48)
      e = 0
      do iz = 0, 1
         do iy = 0, 1
            do ix = 0, 1
               n = 1 + ix + 3*iy + 9*iz
               cn = [n, n + 1, n + 4, n + 3, n + 9, n + 10, n + 13, n + 12]
               do t = 1, 6
                  e = e + 1
                  blk%conn(:, e) = cn(kuhn(:, t))
                  vv = elem_volume(ETYPE_TET4, xm(:, blk%conn(:, e)))
                  if (vv < 0.0_wp) then
                     tmp = blk%conn(2, e); blk%conn(2, e) = blk%conn(3, e)
                     blk%conn(3, e) = tmp
                  end if
                  blk%vol0(e) = abs(vv)
               end do
            end do
         end do
      end do
   end subroutine make_patch

   subroutine reset_block(nel)
      integer, intent(in) :: nel
      blk = elem_block_t()
      blk%nel = nel
      blk%etype = ETYPE_TET4
      blk%nip = 1
      allocate(blk%conn(4, nel), blk%elem(nel), blk%sig(nel, 6, 1), blk%hv(nel, 0, 1))
      allocate(blk%vol0(nel), blk%relvol(nel), blk%eint(nel), blk%ehg(nel), blk%failed(nel))
      blk%sig = 0.0_wp; blk%eint = 0.0_wp; blk%ehg = 0.0_wp; blk%failed = .false.
      blk%relvol = 1.0_wp
      blk%elem = [(i, i = 1, nel)]
      part = part_t()
      part%ihq = 1; part%qh = 0.1_wp; part%q1 = 0.0_wp; part%q2 = 0.0_wp
      if (nel > nv_chunk) stop 'test block too large'
   end subroutine reset_block
end program test_elements
